// The particle solver with the nonlocal contact formulation (Gonzalez &
// Cuitino 2012) in a square die, checked against Hertz forces summed here
// independently, central finite differences of the residual, the closed
// form of the chain between plates (Eqs. 11, 17, solved here by
// bisection), and the balance of the wall forces at equilibrium.

#include "dem/contact/contact_law_registry.h"
#include "dem/contact/pair_properties.h"
#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/nonlocal/square_die_compaction.h"
#include "dem/nonlocal/square_die_deposition.h"
#include "dem/solver/newton_krylov.h"
#include "dem/solver/trust_region_newton.h"

#include "nonlocal_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  using namespace compax::dem;
  using namespace compax::dem::nonlocal_test;

  /// F of Hertz contacts summed pair by pair, Eq. (9) written out here.
  Eigen::VectorXd
  independent_hertz_residual(const ParticleSystem &p, const SquareDie &die)
  {
    const auto n_H
      = [](double R1, double E1, double nu1, double R2, double E2, double nu2) {
          const double inv_E = (1 - nu1 * nu1) / E1
                               + (std::isinf(E2) ? 0.0 : (1 - nu2 * nu2) / E2);
          const double inv_R = 1 / R1 + (std::isinf(R2) ? 0.0 : 1 / R2);
          return 4.0 / 3.0 / inv_E / std::sqrt(inv_R);
        };
    Eigen::VectorXd F = Eigen::VectorXd::Zero(3 * p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        const auto &mi = two_materials[p.materials[i]];
        for (std::size_t j = i + 1; j < p.size(); ++j)
          {
            const auto           &mj = two_materials[p.materials[j]];
            const Eigen::Vector3d d  = p.positions[j] - p.positions[i];
            const double          g  = p.radii[i] + p.radii[j] - d.norm();
            if (g <= 0)
              continue;
            const double P = n_H(p.radii[i],
                                 mi.youngs_modulus,
                                 mi.poisson_ratio,
                                 p.radii[j],
                                 mj.youngs_modulus,
                                 mj.poisson_ratio)
                             * std::pow(g, 1.5);
            F.segment<3>(3 * i) += P * d.normalized();
            F.segment<3>(3 * j) -= P * d.normalized();
          }
        // Walls: the wall pushes the sphere back inside.
        const double half    = 0.5 * die.width;
        const double dist[6] = {p.positions[i][2] - die.lower_punch_height,
                                die.upper_punch_height - p.positions[i][2],
                                p.positions[i][0] + half,
                                half - p.positions[i][0],
                                p.positions[i][1] + half,
                                half - p.positions[i][1]};
        const Eigen::Vector3d into[6] = {
          {0, 0, -1}, {0, 0, 1}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
        for (int f = 0; f < 6; ++f)
          {
            const double g = p.radii[i] - dist[f];
            if (g > 0)
              F.segment<3>(3 * i) += n_H(p.radii[i],
                                         mi.youngs_modulus,
                                         mi.poisson_ratio,
                                         rigid,
                                         rigid,
                                         0.0)
                                     * std::pow(g, 1.5) * into[f];
          }
      }
    return F;
  }

  TEST(NonlocalBedSystem, WithoutNonlocalTermsIsHertz)
  {
    Cluster            c = make_cluster(3);
    NonlocalBedOptions o;
    o.nonlocal = false;
    NonlocalBedSystem system(c.particles, two_materials, c.die, o);
    Eigen::VectorXd   F;
    system.residual(F);
    const Eigen::VectorXd ref = independent_hertz_residual(c.particles, c.die);
    ASSERT_GT(ref.norm(), 0.0);
    EXPECT_LE((F - ref).cwiseAbs().maxCoeff(),
              1e-12 * ref.cwiseAbs().maxCoeff());
    // The nonlocal terms change the forces of the same configuration.
    system.set_nonlocal(true);
    Eigen::VectorXd Fnl;
    system.residual(Fnl);
    ASSERT_TRUE(system.fixed_point().converged);
    EXPECT_GT((Fnl - ref).norm(), 1e-3 * ref.norm());
    // Back to Hertz: the same forces as before, to round-off.
    system.set_nonlocal(false);
    system.residual(Fnl);
    EXPECT_LE((Fnl - ref).cwiseAbs().maxCoeff(),
              1e-12 * ref.cwiseAbs().maxCoeff());
  }

  /// The laws of @p law_name from the registry (at its default parameters)
  /// between spheres of two_materials' elastic constants.
  ContactModel
  registered_model(const std::string &law_name)
  {
    std::vector<ElastoplasticMaterial> materials;
    for (const ElasticMaterial &m : two_materials)
      materials.push_back({m.youngs_modulus, m.poisson_ratio, 150e6, 2.0});
    ContactModel                model(materials, {{0.0, 0.0}, {0.0, 0.0}});
    const RegisteredContactLaw *law = find_contact_law(law_name);
    LawParameterValues          values;
    for (const LawParameter &p : law->parameters)
      values[p.name] = p.default_value;
    model.use_registered_law(*law, values);
    return model;
  }

  // The nonlocal formulation is a layer on the local law of each contact:
  // on the registry's Hertz law it gives the forces of the built-in Hertz
  // contacts (Eq. 9), without and with the nonlocal terms, and the exact
  // Jacobian, whose D = dP/ds now comes from the law, is still the central
  // difference of the residual.
  TEST(NonlocalBedSystem, LayerOnTheRegisteredHertzLawIsTheHertzFormulation)
  {
    for (const bool nonlocal : {false, true})
      {
        Cluster            c = make_cluster(2);
        NonlocalBedOptions o = converged_fixed_point(1e-15, nonlocal);
        NonlocalBedSystem  built_in(c.particles, two_materials, c.die, o);
        o.local_laws = registered_model("hertz");
        NonlocalBedSystem layered(c.particles, two_materials, c.die, o);
        Eigen::VectorXd   F, G;
        BlockSparseMatrix K;
        built_in.residual(F);
        layered.assemble(G, K);
        ASSERT_GT(F.norm(), 0.0);
        EXPECT_LE((G - F).cwiseAbs().maxCoeff(),
                  1e-12 * F.cwiseAbs().maxCoeff())
          << "nonlocal " << nonlocal;
        expect_jacobian_is_central_difference(layered, K, 3, 1e-8 * 100e-6);
      }
  }

  // Gonzalez & Cuitino's far field shifts the argument of an elastic law;
  // a law with internal variables (the hysteretic spring's largest overlap,
  // the bonded law's plastic radius and bridge) is refused by name.
  TEST(NonlocalBedSystem, RefusesALocalLawWithInternalVariables)
  {
    Cluster            c = make_cluster(1);
    NonlocalBedOptions o;
    o.local_laws = registered_model("walton-braun");
    try
      {
        NonlocalBedSystem system(c.particles, two_materials, c.die, o);
        ADD_FAILURE() << "a Walton-Braun law was accepted";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("walton-braun"), std::string::npos)
          << e.what();
      }
    o.local_laws
      = ContactModel({{19e9, 0.30, 150e6, 2.0}, {7e9, 0.2, 150e6, 2.0}},
                     {{1e6, 1e6}, {1e6, 1e6}});
    EXPECT_THROW(NonlocalBedSystem(c.particles, two_materials, c.die, o),
                 std::invalid_argument);
  }

  TEST(NonlocalBedSystem, JacobianIsCentralDifferenceOfResidual)
  {
    for (const bool nonlocal : {false, true})
      for (unsigned int seed : {1u, 2u, 5u})
        {
          Cluster           c = make_cluster(seed);
          NonlocalBedSystem system(c.particles,
                                   two_materials,
                                   c.die,
                                   converged_fixed_point(1e-15, nonlocal));
          Eigen::VectorXd   F;
          BlockSparseMatrix K;
          system.assemble(F, K);
          ASSERT_TRUE(F.allFinite());
          const auto d = expect_jacobian_is_central_difference(system,
                                                               K,
                                                               seed,
                                                               1e-8 * 100e-6);
          // The approximate K is exact for Hertz (checked with J v) and
          // only approximate with the nonlocal terms.
          if (nonlocal)
            {
              EXPECT_GT((d.Kv - d.fd).norm(), 1e-3 * d.fd.norm());
            }
        }
  }

  TEST(NonlocalBedSystem, NonlocalJacobianIsNotSymmetric)
  {
    // The angle dependence of the influence coefficients: u.J v != v.J u,
    // so no potential exists (documented in NonlocalBedSystem).
    Cluster            c = make_cluster(7);
    NonlocalBedOptions o;
    o.fixed_point_tolerance = 1e-15;
    NonlocalBedSystem system(c.particles, two_materials, c.die, o);
    Eigen::VectorXd   F, Ju, Jv;
    system.residual(F);
    std::mt19937                     gen(11);
    std::normal_distribution<double> normal;
    Eigen::VectorXd                  u(F.size()), v(F.size());
    for (Eigen::Index k = 0; k < v.size(); ++k)
      {
        u[k] = normal(gen);
        v[k] = normal(gen);
      }
    system.apply_jacobian(u, Ju);
    system.apply_jacobian(v, Jv);
    const double scale = Ju.norm() * v.norm();
    EXPECT_GT(std::abs(v.dot(Ju) - u.dot(Jv)), 1e-8 * scale);
  }

  TEST(NonlocalBedSystem, SolverReachesChainClosedForm)
  {
    const double                       R = 0.01, E = 1.85e6, nu = 0.46;
    const std::vector<ElasticMaterial> rubber{{E, nu}};
    for (const unsigned int n : {1u, 3u})
      for (const double eps : {0.002, 0.02})
        for (const bool krylov : {false, true})
          {
            const double      Delta = 2.0 * n * R * eps;
            Cluster           c     = make_chain(n, R, Delta);
            NonlocalBedSystem system(c.particles, rubber, c.die);
            bool              converged;
            if (krylov)
              converged = NewtonKrylov().solve(system).converged;
            else
              converged = TrustRegionNewton().solve(system).converged;
            ASSERT_TRUE(converged) << n << ' ' << eps << ' ' << krylov;
            const double P = chain_force(n, R, E, nu, Delta);
            expect_punch_forces(system, P, 1e-6);
            // Eq. (17): D = a eps^{1/2} + 7/(24 pi^2) b^2 eps + O(eps^{3/2})
            // with eps = Delta / (2 N R) (gamma / 2R of a
            // sphere-sphere contact).
            const double e     = Delta / (2.0 * n * R);
            const double b     = (3 - 2 * nu) / (1 - nu);
            const double hertz = 4.0 / 3.0 * E / (1 - nu * nu) * std::sqrt(R)
                                 * std::pow(Delta / (2.0 * n), 1.5);
            const double D = P / hertz - 1.0;
            const double D17
              = b / (2 * pi) * std::sqrt(e) + 7 / (24 * pi * pi) * b * b * e;
            EXPECT_NEAR(D, D17, 3.0 * std::pow(e, 1.5) * b * b * b);
          }
  }

  TEST(NonlocalBedSystem, SquareDieBedBalancesWallForces)
  {
    const Cluster         bed = deposited_square_die_bed(1e-3, {40, 6}, 4);
    const ParticleSystem &p   = bed.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        // Inside the die.
        EXPECT_LE(std::abs(p.positions[i][0]) + p.radii[i],
                  0.5e-3 * (1 + 1e-12));
        EXPECT_LE(std::abs(p.positions[i][1]) + p.radii[i],
                  0.5e-3 * (1 + 1e-12));
        EXPECT_GE(p.positions[i][2] - p.radii[i], -1e-12 * p.radii[i]);
      }
    BedCompactionOptions o;
    o.final_density    = 0.60;
    o.density_step     = 0.01;
    o.jamming_pressure = 2e5;
    for (const bool nonlocal : {false, true})
      {
        const BedCompactionResult r
          = compact_square_die_bed(p, two_materials, bed.die, nonlocal, o);
        ASSERT_TRUE(r.complete) << r.stop_reason;
        const BedCompactionPoint &last = r.points.back();
        ASSERT_TRUE(last.jammed);
        const auto &w = last.wall_force;
        // Newton's third law at equilibrium (no gravity): opposite walls
        // carry the same force.
        const double tol = 1e-4 * w[SquareDie::upper_punch];
        expect_opposite_walls_balance(w, tol);
        EXPECT_GT(w[SquareDie::x_lower], 0.0);
      }
  }
} // namespace
