#pragma once

#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_sums.h"
#include "dem/solver/equilibrium_system.h"

#include <Eigen/Core>
#include <Eigen/SparseLU>

#include <iosfwd>

namespace compax::dem
{
  /// Tolerances of NewtonKrylov.
  struct NewtonKrylovOptions
  {
    /// Converged when max_i |F_i| <= force_tolerance times the mean contact
    /// force ...
    double force_tolerance = 1e-6;
    /// ... and the last step moved no particle farther than this fraction
    /// of the mean radius [-].
    double step_tolerance = 1e-4;
    int    max_iterations = 60;
    /// Consecutive iterations that reduce |F| by less than 10 % after
    /// which the solve gives up (near-singular J; the caller goes on with
    /// a globally convergent method) [-].
    int stall_iterations = 4;
    /// GMRES: Krylov dimension before a restart, total iterations, and the
    /// relative residual of each linear solve [-].
    int    restart          = 40;
    int    max_linear       = 400;
    double linear_tolerance = 1e-4;
    /// Shift of the preconditioner K_approx + shift * mean diagonal (keeps
    /// rattlers' zero rows invertible) [-].
    double preconditioner_shift = 1e-6;
    /// One line per iteration (diagnostics); null for none.
    std::ostream *trace = nullptr;
  };

  /// Outcome of NewtonKrylov::solve().
  struct NewtonKrylovResult
  {
    bool        converged         = false;
    int         iterations        = 0;
    int         linear_iterations = 0;
    int         residuals         = 0;
    int         backtracks        = 0;
    double      relative_residual = 0.0;
    ContactSums sums;
  };

  /**
   * Newton's method with the exact Jacobian of a system
   * (EquilibriumSystem::apply_exact_jacobian; the assembled K where the
   * system has none other, as every local contact law), also for a field
   * that is not the gradient of an energy (the nonlocal formulation: d
   * gamma_NL / dx through the linearized fixed point, and the turning
   * contact directions): the linear systems J s = -F, J not symmetric in
   * general, are solved by restarted GMRES, right preconditioned by a
   * sparse LU of the assembled K; the step is capped at a quarter of the
   * Verlet skin per particle and accepted by backtracking on the residual
   * norm |F| (Armijo), the merit function of a nonconservative system,
   * instead of the energy decrease of the trust region. Meant for jammed
   * beds near equilibrium (the last iterations of a solve, see
   * EquilibriumOptions::krylov_switch); floppy, unjammed beds need FIRE or
   * the trust region.
   */
  class NewtonKrylov
  {
  public:
    explicit NewtonKrylov(NewtonKrylovOptions options = {});

    NewtonKrylovResult
    solve(EquilibriumSystem &system);

  private:
    /// GMRES(m) for J s = b with right preconditioner; returns iterations.
    int
    gmres(EquilibriumSystem &system, const Eigen::VectorXd &b);

    /// Jv = J v: the system's exact Jacobian, or the assembled K.
    void
    apply_jacobian(EquilibriumSystem     &system,
                   const Eigen::VectorXd &v,
                   Eigen::VectorXd       &Jv) const;

    NewtonKrylovOptions                          opts;
    BlockSparseMatrix                            K;
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    Eigen::VectorXd                              F, F_trial, s, x_old, w, z;
    Eigen::MatrixXd                              V, Z, H;
  };
} // namespace compax::dem
