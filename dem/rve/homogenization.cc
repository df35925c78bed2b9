#include "dem/rve/homogenization.h"

#include "dem/rve/periodic_bed_system.h"
#include "dem/solver/pair_block.h"

#include <Eigen/SparseCholesky>

#include <limits>
#include <stdexcept>
#include <string>

namespace compax::dem
{
  namespace
  {
    /// Voigt index -> tensor indices, order (xx, yy, zz, yz, xz, xy).
    constexpr int voigt_row[6] = {0, 1, 2, 1, 0, 0};
    constexpr int voigt_col[6] = {0, 1, 2, 2, 2, 1};

    /// The unit strain of Voigt direction beta (engineering shear 1).
    Eigen::Matrix3d
    unit_strain(const int beta)
    {
      Vector6d v = Vector6d::Zero();
      v[beta]    = 1.0;
      return strain_from_voigt(v);
    }
  } // namespace

  Vector6d
  to_voigt(const Eigen::Matrix3d &t)
  {
    Vector6d v;
    for (int b = 0; b < 6; ++b)
      v[b]
        = 0.5 * (t(voigt_row[b], voigt_col[b]) + t(voigt_col[b], voigt_row[b]));
    return v;
  }

  Eigen::Matrix3d
  strain_from_voigt(const Vector6d &v)
  {
    Eigen::Matrix3d e;
    e << v[0], 0.5 * v[5], 0.5 * v[4], //
      0.5 * v[5], v[1], 0.5 * v[3],    //
      0.5 * v[4], 0.5 * v[3], v[2];
    return e;
  }

  Eigen::Matrix3d
  love_weber_stress(const PeriodicBed &bed)
  {
    const ParticleSystem &p = bed.particles;
    Eigen::Matrix3d       S = Eigen::Matrix3d::Zero();
    for (const PeriodicContact &c : bed.contacts.pairs)
      {
        const PeriodicContactGeometry g = contact_geometry(p, bed.cell, c);
        if (!g.may_act)
          continue;
        const double force
          = periodic_contact_response(c, g.overlap, ContactBranch::current)
              .force;
        if (force != 0.0)
          S.noalias() -= (force / g.distance) * g.branch * g.branch.transpose();
      }
    return S / bed.cell.volume();
  }

  CellTangents
  TangentCalculator::compute(PeriodicBed        &bed,
                             const ContactModel &model,
                             const ContactBranch branch)
  {
    const ParticleSystem &p = bed.particles;
    const std::size_t     n = p.size();
    assembler.assemble(bed, model, F, K, branch);

    // A (affine derivative of S = sum_c g (x) d) and G (out-of-balance
    // forces of the affine motion), column by column.
    Matrix6d        A = Matrix6d::Zero();
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(3 * n, 6);
    Eigen::Matrix3d E[6];
    for (int b = 0; b < 6; ++b)
      E[b] = unit_strain(b);
    for (const PeriodicContact &c : bed.contacts.pairs)
      {
        const PeriodicContactGeometry at = contact_geometry(p, bed.cell, c);
        if (!at.may_act)
          continue;
        const ContactResponse r
          = periodic_contact_response(c, at.overlap, branch);
        if (r.force == 0.0 && r.stiffness == 0.0)
          continue;
        const Eigen::Vector3d &d = at.branch;
        const Eigen::Vector3d  n = d / at.distance;
        const Eigen::Matrix3d  k = PairBlock(r, at.distance).matrix(n);
        const Eigen::Vector3d  g = -r.force * n;
        for (int b = 0; b < 6; ++b)
          {
            const Eigen::Vector3d dd = E[b] * d;
            const Eigen::Vector3d kd = k * dd;
            A.col(b) += to_voigt(kd * d.transpose() + g * dd.transpose());
            G.block<3, 1>(3 * c.i, b) += kd;
            G.block<3, 1>(3 * c.j, b) -= kd;
          }
      }

    CellTangents    t;
    Eigen::MatrixXd X(3 * n, 6);
    if (method == Method::direct || !solve_iteratively(G, X, t.cg_iterations))
      {
        solve_directly(G, X);
        t.direct = true;
      }

    const double   V     = bed.cell.volume();
    const Vector6d sigma = to_voigt(love_weber_stress(bed));
    Vector6d       trace = Vector6d::Zero();
    trace.head<3>().setOnes();
    t.affine    = A / V - sigma * trace.transpose();
    t.condensed = (A - G.transpose() * X) / V - sigma * trace.transpose();
    return t;
  }

  bool
  TangentCalculator::solve_iteratively(const Eigen::MatrixXd &G,
                                       Eigen::MatrixXd       &X,
                                       int                   &iterations)
  {
    M.compute(K);
    const int max_iterations = 10 * static_cast<int>(G.rows()) + 100;
    for (int b = 0; b < 6; ++b)
      {
        g = G.col(b);
        if (g.squaredNorm() == 0.0)
          {
            X.col(b).setZero();
            continue;
          }
        // Steihaug-Toint without a radius is PCG on g.s + s.K s / 2:
        // s = -K^{-1} g unless it meets negative curvature.
        const SteihaugResult r
          = cg.solve(K,
                     M,
                     g,
                     std::numeric_limits<double>::infinity(),
                     1e-6,
                     max_iterations,
                     s);
        iterations += r.iterations;
        if (r.negative_curvature || r.iterations >= max_iterations)
          return false;
        X.col(b) = -s;
      }
    return true;
  }

  void
  TangentCalculator::solve_directly(const Eigen::MatrixXd &G,
                                    Eigen::MatrixXd       &X) const
  {
    Eigen::SparseMatrix<double> Ks            = K.to_sparse();
    double                      mean_diagonal = 0.0;
    for (Eigen::Index i = 0; i < Ks.rows(); ++i)
      mean_diagonal += std::abs(Ks.coeff(i, i));
    mean_diagonal = Ks.rows() > 0 ? mean_diagonal / Ks.rows() : 1.0;
    if (!(mean_diagonal > 0.0))
      mean_diagonal = 1.0;
    for (Eigen::Index i = 0; i < Ks.rows(); ++i)
      Ks.coeffRef(i, i) += 1e-10 * mean_diagonal;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Ks);
    if (ldlt.info() != Eigen::Success)
      throw std::runtime_error("RVE tangent: factorization of K failed");
    X = ldlt.solve(G);
  }

  Matrix6d
  finite_difference_tangent(const PeriodicBed        &bed,
                            const ContactModel       &model,
                            const double              h,
                            const EquilibriumOptions &options)
  {
    PeriodicAssembler assembler;
    TrustRegionNewton newton(options);
    auto              stress_at = [&](const Eigen::Matrix3d &strain) {
      PeriodicBed strained = bed;
      map_affinely(strained,
                   (Eigen::Matrix3d::Identity() + strain) * bed.deformation);
      PeriodicBedSystem       system(strained, model, assembler);
      const EquilibriumResult r = newton.solve(system);
      if (!r.converged)
        throw std::runtime_error(
          "finite-difference tangent: equilibrium did not converge (residual "
          + std::to_string(r.relative_residual * 1e12) + "e-12" + " after "
          + std::to_string(r.work.iterations) + " iterations)");
      return to_voigt(love_weber_stress(strained));
    };
    Matrix6d C;
    for (int b = 0; b < 6; ++b)
      {
        const Eigen::Matrix3d E = unit_strain(b);
        C.col(b) = (stress_at(h * E) - stress_at(-h * E)) / (2.0 * h);
      }
    return C;
  }
} // namespace compax::dem
