#pragma once

#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/nonlocal/nonlocal_newton.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/fire_relaxation.h"
#include "dem/solver/steihaug_cg.h"
#include "dem/solver/trial_step.h"
#include "dem/solver/trust_radius.h"

#include <Eigen/Core>

#include <iosfwd>

namespace compax::dem
{
  /// Tolerances and limits of NonlocalTrustRegion.
  struct NonlocalTrustRegionOptions
  {
    /// Converged when max_i |F_i| <= force_tolerance times the mean contact
    /// force and the last step moved no particle farther than
    /// step_tolerance times the mean radius [-].
    double force_tolerance = 1e-6;
    double step_tolerance  = 1e-4;
    /// Trust-region iterations before the solve counts as failed.
    int max_iterations = 300;
    /// Largest forcing term of the inexact CG solves [-].
    double max_forcing = 0.1;
    /// Eigenvalue floor of the block-Jacobi preconditioner (from the
    /// approximate K) relative to its mean diagonal [-].
    double preconditioner_floor = 1e-3;
    int    max_cg_iterations    = 400;
    /// Initial and largest trust radius as fractions of R_mean sqrt(N) [-].
    double initial_radius = 0.05;
    double max_radius     = 0.5;
    /// Start every solve at initial_radius (a new load step) instead of
    /// the radius the previous solve ended with.
    bool reset_radius = true;
    /// Below this relative residual the exact-Jacobian Newton-Krylov
    /// finishes the solve (quadratic convergence); 0 never [-].
    double krylov_switch = 1e-2;
    /// Iterations without a tenfold drop of the residual after which FIRE
    /// relaxes the bed (rearrangement); FIRE iterations per fallback.
    int    stall_iterations = 40;
    int    fire_iterations  = 5000;
    double fire_tolerance   = 1e-3;
    /// One line per iteration; null for none.
    std::ostream *trace = nullptr;
  };

  /// Outcome of NonlocalTrustRegion::solve().
  struct NonlocalTrustRegionResult
  {
    bool   converged         = false;
    int    iterations        = 0;
    int    cg_iterations     = 0;
    int    rejected_steps    = 0;
    int    krylov_iterations = 0;
    int    fire_iterations   = 0;
    double relative_residual = 0.0;
  };

  /**
   * Trust-region Newton method for the static equilibrium of a
   * NonlocalBedSystem whose model Hessian is the frozen-angle Jacobian
   * H = G^T (D^-1 - C)^-1 G + geometric terms
   * (NonlocalBedSystem::apply_jacobian with turning = false), applied
   * matrix-free inside Steihaug-Toint CG preconditioned by the block
   * Jacobi of the approximate (local-stiffness) K. H is the exact Hessian
   * of Phi = sum_c U(s_c) - P.C P / 2 at frozen contact directions, i.e.
   * of the nonlocal formulation without the (small, nonsymmetric) turning
   * of the influence coefficients; unlike the local stiffness it has the
   * amplification (I - D C)^-1 of the nonlocal terms, so its steps are not
   * too long where the contacts interact strongly.
   *
   * Acceptance as in TrustRegionNewton: the actual decrease is the
   * trapezoidal work -(F(x) + F(x+s)).s / 2 against the model decrease.
   * Steps are clipped particle by particle (a quarter of the Verlet skin,
   * and gaps the model does not see, NonlocalBedSystem::limit_closing).
   * Once the residual is below krylov_switch the exact Jacobian takes over
   * (NonlocalNewtonKrylov, quadratic convergence); if that fails the trust
   * region goes on from where it stopped. FIRE with the nonlocal forces is
   * the fallback when the iteration stalls (a rearranging, unjammed bed).
   */
  class NonlocalTrustRegion
  {
  public:
    explicit NonlocalTrustRegion(NonlocalTrustRegionOptions options = {},
                                 NewtonKrylovOptions        krylov  = {});

    NonlocalTrustRegionResult
    solve(NonlocalBedSystem &system);

    const NonlocalTrustRegionOptions &
    options() const
    {
      return opts;
    }

  private:
    NonlocalTrustRegionOptions opts;
    NonlocalNewtonKrylov       krylov;
    FireRelaxation             fire;
    BlockSparseMatrix          K;
    BlockJacobiPreconditioner  M;
    SteihaugCG                 cg;
    TrialStep                  trial;
    Eigen::VectorXd            F, s, Hp, Ms, factor;
    TrustRadius                radius;
  };
} // namespace compax::dem
