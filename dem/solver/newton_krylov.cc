#include "dem/solver/newton_krylov.h"

#include "dem/solver/residual_norms.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace compax::dem
{
  NewtonKrylov::NewtonKrylov(const NewtonKrylovOptions options)
      : opts(options)
  {
  }

  void
  NewtonKrylov::apply_jacobian(EquilibriumSystem     &system,
                               const Eigen::VectorXd &v,
                               Eigen::VectorXd       &Jv) const
  {
    if (!system.apply_exact_jacobian(v, Jv))
      K.vmult(Jv, v);
  }

  int
  NewtonKrylov::gmres(EquilibriumSystem &system, const Eigen::VectorXd &b)
  {
    const Eigen::Index n = b.size();
    const int          m = std::max(1, opts.restart);
    V.resize(n, m + 1);
    Z.resize(n, m);
    H.setZero(m + 1, m);
    s.setZero(n);
    const double b_norm = b.norm();
    if (b_norm == 0.0)
      return 0;
    int             total = 0;
    Eigen::VectorXd cs(m), sn(m), g(m + 1);
    while (total < opts.max_linear)
      {
        // r = b - J s
        apply_jacobian(system, s, w);
        Eigen::VectorXd r    = b - w;
        double          beta = r.norm();
        if (beta <= opts.linear_tolerance * b_norm)
          break;
        V.col(0) = r / beta;
        g.setZero();
        g[0] = beta;
        H.setZero();
        int k = 0;
        for (; k < m && total < opts.max_linear; ++k, ++total)
          {
            z        = lu.solve(V.col(k));
            Z.col(k) = z;
            apply_jacobian(system, z, w);
            for (int i = 0; i <= k; ++i)
              {
                H(i, k) = w.dot(V.col(i));
                w -= H(i, k) * V.col(i);
              }
            H(k + 1, k) = w.norm();
            if (H(k + 1, k) > 0.0)
              V.col(k + 1) = w / H(k + 1, k);
            for (int i = 0; i < k; ++i)
              {
                const double t = cs[i] * H(i, k) + sn[i] * H(i + 1, k);
                H(i + 1, k)    = -sn[i] * H(i, k) + cs[i] * H(i + 1, k);
                H(i, k)        = t;
              }
            const double rr = std::hypot(H(k, k), H(k + 1, k));
            cs[k]           = rr > 0.0 ? H(k, k) / rr : 1.0;
            sn[k]           = rr > 0.0 ? H(k + 1, k) / rr : 0.0;
            H(k, k)         = rr;
            H(k + 1, k)     = 0.0;
            g[k + 1]        = -sn[k] * g[k];
            g[k]            = cs[k] * g[k];
            if (std::abs(g[k + 1]) <= opts.linear_tolerance * b_norm)
              {
                ++k;
                ++total;
                break;
              }
          }
        // s += Z H^{-1} g
        Eigen::VectorXd coef
          = H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(
            g.head(k));
        s += Z.leftCols(k) * coef;
        if (std::abs(g[k]) <= opts.linear_tolerance * b_norm)
          break;
      }
    return total;
  }

  NewtonKrylovResult
  NewtonKrylov::solve(EquilibriumSystem &system)
  {
    NewtonKrylovResult result;
    const double       R = system.mean_radius();
    const auto relative  = [](const Eigen::VectorXd &f, const ContactSums &s) {
      return f.allFinite() ? relative_residual(f, s)
                            : std::numeric_limits<double>::infinity();
    };
    result.sums = system.assemble(F, K);
    ++result.residuals;
    double last_step = std::numeric_limits<double>::infinity();
    int    stalled   = 0;
    for (int it = 0;; ++it)
      {
        result.relative_residual = relative(F, result.sums);
        if (result.relative_residual <= opts.force_tolerance
            && (it == 0 || last_step <= opts.step_tolerance * R))
          {
            result.converged = true;
            break;
          }
        if (it >= opts.max_iterations
            || !std::isfinite(result.relative_residual))
          break;

        // Preconditioner: LU of the shifted approximate stiffness.
        Eigen::SparseMatrix<double> A         = K.to_sparse();
        double                      mean_diag = 0.0;
        for (Eigen::Index i = 0; i < A.rows(); ++i)
          mean_diag += std::abs(A.coeff(i, i));
        mean_diag /= std::max<Eigen::Index>(1, A.rows());
        for (Eigen::Index i = 0; i < A.rows(); ++i)
          A.coeffRef(i, i) += opts.preconditioner_shift * mean_diag;
        lu.compute(A);
        if (lu.info() != Eigen::Success)
          break;
        const int lin = gmres(system, -F);
        result.linear_iterations += lin;
        ++result.iterations;
        if (opts.trace)
          {
            apply_jacobian(system, s, w);
            *opts.trace << "  nk it " << it << " rel "
                        << result.relative_residual << " |F| " << F.norm()
                        << " gmres " << lin << " lin.res "
                        << (w + F).norm() / F.norm() << " step "
                        << max_particle_norm(s) / R;
          }

        // Cap every particle's move at a quarter of the skin.
        const double longest = max_particle_norm(s);
        if (longest > 0.25 * system.skin())
          s *= 0.25 * system.skin() / longest;

        // Backtracking on |F|.
        auto         x      = system.coordinates();
        const double f_norm = F.norm();
        x_old               = x;
        double alpha        = 1.0;
        bool   accepted     = false;
        for (int b = 0; b < 30; ++b)
          {
            x                       = x_old + alpha * s;
            const ContactSums trial = system.residual(F_trial);
            ++result.residuals;
            if (F_trial.allFinite()
                && F_trial.norm() <= (1.0 - 1e-4 * alpha) * f_norm)
              {
                accepted = true;
                break;
              }
            (void)trial;
            alpha *= 0.5;
            ++result.backtracks;
          }
        if (!accepted)
          {
            if (opts.trace)
              *opts.trace << " rejected\n";
            x           = x_old;
            result.sums = system.assemble(F, K);
            ++result.residuals;
            break;
          }
        last_step = alpha * max_particle_norm(s);
        // Stagnation (a nearly singular J: huge steps cut back to nothing):
        // give up early and let the caller go on.
        stalled = F_trial.norm() > 0.9 * f_norm ? stalled + 1 : 0;
        if (opts.trace)
          *opts.trace << " alpha " << alpha << " |F_new| " << F_trial.norm()
                      << '\n';
        result.sums = system.assemble(F, K);
        ++result.residuals;
        if (stalled >= opts.stall_iterations)
          {
            result.relative_residual = relative(F, result.sums);
            break;
          }
      }
    return result;
  }
} // namespace compax::dem
