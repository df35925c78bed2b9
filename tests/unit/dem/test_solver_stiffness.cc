#include "dem/parallel_particles.h"
#include "dem/solver/contact_assembler.h"
#include "tests/support/gonzalez_material1.h"
#include "tests/support/pressed_lattice.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <random>

using namespace compax::dem;
namespace material1 = compax::testing::material1;

/// K = dF/dx against a central finite difference of F on a small random
/// bed whose contacts are in plastic loading, in elastic unloading with a
/// solid bridge (a < a_B = a_p), and against the punches and the die wall.
TEST(SolverStiffness, EqualsCentralDifferenceOfResidual)
{
  const ContactModel model = material1::contact_model();
  const double       R     = material1::R;

  Bed bed;
  // Spacing 0.94 (2R): every face neighbour overlaps by 0.045R..0.2R, far
  // from the onset of contact where P'' is unbounded; the corner
  // particles press into the die wall, the layers into the punches.
  const double a        = 2 * R * 0.94;
  bed.walls.diameter    = 2 * (std::sqrt(2.0) * a + R - 0.05 * R);
  bed.walls.lower_punch = 0.0;
  bed.walls.upper_punch = a + 2 * R * 0.94;
  bed.contacts.set_skin(0.5 * R);
  std::mt19937_64 rng(42);
  auto            u = [&]() { return (rng() >> 11) * 0x1.0p-53 - 0.5; };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        {
          Eigen::Vector3d x((i - 1) * a, (j - 1) * a, R * 0.94 + k * a);
          x += 0.02 * R * Eigen::Vector3d(u(), u(), u());
          bed.particles.add(x, R * (1.0 + 0.04 * u()));
        }
  bed.contacts.rebuild(bed.particles, bed.walls, model);

  // Every other loaded pair is put on its elastic unloading branch.
  int n_unloading = 0, n_loading = 0, n_wall = 0;
  for (std::size_t k = 0; k < bed.contacts.pairs.size(); ++k)
    {
      PairContact &c     = bed.contacts.pairs[k];
      const double gamma = pair_overlap(bed.particles, c);
      if (gamma <= 0.0)
        continue;
      if (k % 2 == 0)
        {
          ++n_loading;
          continue;
        }
      // gamma = gamma_p - 0.3 (gamma_p - gamma_break(a_p)), by fixed point.
      double a_p = bonded_law(c.law).plastic_radius(gamma);
      for (int it = 0; it < 50; ++it)
        {
          const double drop = bonded_law(c.law).plastic_overlap(a_p)
                              - bonded_law(c.law).breakage_overlap(a_p);
          a_p = bonded_law(c.law).plastic_radius(gamma + 0.3 * drop);
        }
      c.history[BondedElastoplasticLaw::a_p_slot] = a_p;
      c.history[BondedElastoplasticLaw::a_B_slot] = a_p;
      ++n_unloading;
    }
  for (const auto &c : bed.contacts.walls)
    n_wall
      += bed.walls.gap(c.wall, bed.particles.positions[c.i], R).overlap > 0.0;
  ASSERT_GE(n_loading, 3);
  ASSERT_GE(n_unloading, 3);
  ASSERT_GE(n_wall, 3);

  ContactAssembler  assembler;
  BlockSparseMatrix K;
  Eigen::VectorXd   F, Fp, Fm;
  assembler.assemble(bed, model, F, K);
  const Eigen::MatrixXd Kd(K.to_sparse());
  EXPECT_LT((Kd - Kd.transpose()).norm(), 1e-12 * Kd.norm());

  const double    h = 1e-10;
  Eigen::MatrixXd fd(Kd.rows(), Kd.cols());
  auto            x = bed.particles.coordinates();
  for (Eigen::Index k = 0; k < x.size(); ++k)
    {
      const double x0 = x[k];
      x[k]            = x0 + h;
      assembler.residual(bed, model, Fp);
      x[k] = x0 - h;
      assembler.residual(bed, model, Fm);
      x[k]      = x0;
      fd.col(k) = (Fp - Fm) / (2 * h);
    }
  for (Eigen::Index k = 0; k < x.size(); ++k)
    EXPECT_LT((Kd.col(k) - fd.col(k)).norm(), 1e-6 * Kd.col(k).norm())
      << "column " << k;
  EXPECT_LT((Kd - fd).norm(), 1e-6 * Kd.norm());
}

/// The residual of a bed large enough to be evaluated on every thread
/// (ContactAssembler::parallel_pairs) is the serial sum of assemble() to
/// the bit, on any number of threads, so that a run's results do not
/// depend on the cores it had; and its pair forces cancel (action equals
/// reaction): the net force of the bed is that of the walls alone.
TEST(SolverStiffness, ThreadedResidualIsTheSerialSumToTheBit)
{
  const ContactModel model = material1::contact_model();
  Bed bed = compax::testing::pressed_lattice(model, material1::R, 24);
  ASSERT_GE(bed.contacts.pairs.size(), ContactAssembler::parallel_pairs);

  const int         threads_before = omp_get_max_threads();
  ContactAssembler  assembler;
  BlockSparseMatrix K;
  Eigen::VectorXd   threaded, serial;
  const ContactSums s_serial = assembler.assemble(bed, model, serial, K);
  ASSERT_GT(s_serial.n_loaded, bed.particles.size());
  ContactSums s_threaded;
  for (const int threads : {1, 2, 3})
    {
      omp_set_num_threads(threads);
      s_threaded = assembler.residual(bed, model, threaded);
      EXPECT_EQ(s_threaded.n_loaded, s_serial.n_loaded) << threads;
      EXPECT_EQ(s_threaded.mean_force, s_serial.mean_force) << threads;
      EXPECT_TRUE(threaded == serial)
        << threads << " threads: largest difference "
        << (threaded - serial).lpNorm<Eigen::Infinity>() << " N";
    }
  omp_set_num_threads(threads_before);

  // Action equals reaction: the pairs add nothing to the net force, so
  // sum_i F_i is the punches' force along z (the bed touches no die wall).
  Eigen::Vector3d net = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < bed.particles.size(); ++i)
    net += threaded.segment<3>(3 * i);
  const double punches
    = s_threaded.wall_force[static_cast<int>(Wall::lower_punch)]
      - s_threaded.wall_force[static_cast<int>(Wall::upper_punch)];
  EXPECT_NEAR(net[0], 0.0, 1e-9 * s_serial.mean_force);
  EXPECT_NEAR(net[1], 0.0, 1e-9 * s_serial.mean_force);
  EXPECT_NEAR(net[2], -punches, 1e-9 * std::abs(punches) + 1e-9);
}

/// The assembly of F and K of a bed large enough to be evaluated on every
/// thread is the serial one to the bit on 1, 2 and 3 threads, on both
/// branches of the law, with histories committed (Eq. 13 at the pressed
/// state, so the unloading branch differs from the current one); and its
/// F is the residual's. Each assembly has a matrix of its own (the
/// pattern follows it, even at the address of a destroyed one).
TEST(SolverStiffness, ThreadedAssemblyIsTheSerialOneToTheBit)
{
  const ContactModel model = material1::contact_model();
  Bed bed = compax::testing::pressed_lattice(model, material1::R, 24);
  ASSERT_GE(bed.contacts.pairs.size(), ContactAssembler::parallel_pairs);
  ContactAssembler assembler;
  Eigen::VectorXd  F;
  assembler.residual(bed, model, F);
  ASSERT_GT(bed.contacts.update_histories(bed.particles, bed.walls).formed, 0u);

  const int                        threads_before = omp_get_max_threads();
  std::vector<std::vector<double>> serial_values;
  for (const ContactBranch branch :
       {ContactBranch::current, ContactBranch::unloading})
    {
      omp_set_num_threads(1);
      BlockSparseMatrix K_serial;
      Eigen::VectorXd   F_serial, residual;
      const ContactSums s_serial
        = assembler.assemble(bed, model, F_serial, K_serial, branch);
      ASSERT_GT(s_serial.n_loaded, bed.particles.size());
      const std::vector<double> serial(K_serial.block(0),
                                       K_serial.block(K_serial.n_blocks()));
      serial_values.push_back(serial);
      for (const int threads : {2, 3})
        {
          omp_set_num_threads(threads);
          BlockSparseMatrix K;
          const ContactSums s = assembler.assemble(bed, model, F, K, branch);
          ASSERT_EQ(K.n_blocks(), K_serial.n_blocks());
          EXPECT_EQ(s.n_loaded, s_serial.n_loaded) << threads;
          EXPECT_EQ(s.mean_force, s_serial.mean_force) << threads;
          EXPECT_TRUE(F == F_serial) << threads << " threads";
          EXPECT_TRUE(std::equal(serial.begin(), serial.end(), K.block(0)))
            << threads << " threads";
          assembler.residual(bed, model, residual);
          EXPECT_TRUE(residual == F) << threads << " threads";
        }
    }
  omp_set_num_threads(threads_before);
  // The branches differ: the plastic contacts unload elastically.
  EXPECT_FALSE(serial_values[0] == serial_values[1]);
}

/// K x on a bed above vmult()'s threading threshold (a pressed lattice of
/// 13 824 spheres): the same to the bit on 1, 2 and 3 threads, and equal
/// to Eigen's product with the same matrix as an Eigen::SparseMatrix to
/// round-off.
TEST(SolverStiffness, ThreadedStiffnessProductIsTheSerialOneToTheBit)
{
  const ContactModel model = material1::contact_model();
  Bed bed = compax::testing::pressed_lattice(model, material1::R, 24);
  ASSERT_GE(static_cast<std::ptrdiff_t>(bed.particles.size()),
            parallel_particles);

  ContactAssembler  assembler;
  BlockSparseMatrix K;
  Eigen::VectorXd   F;
  assembler.assemble(bed, model, F, K);
  std::mt19937_64                        rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd                        x(F.size());
  for (Eigen::Index k = 0; k < x.size(); ++k)
    x[k] = u(rng);

  const Eigen::VectorXd reference      = K.to_sparse() * x;
  const int             threads_before = omp_get_max_threads();
  Eigen::VectorXd       serial(x.size()), threaded(x.size());
  omp_set_num_threads(1);
  K.vmult(serial, x);
  EXPECT_LT((serial - reference).lpNorm<Eigen::Infinity>(),
            1e-13 * reference.lpNorm<Eigen::Infinity>());
  for (const int threads : {2, 3})
    {
      omp_set_num_threads(threads);
      K.vmult(threaded, x);
      EXPECT_TRUE(threaded == serial) << threads << " threads";
    }
  omp_set_num_threads(threads_before);
}
