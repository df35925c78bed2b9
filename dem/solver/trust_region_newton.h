#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/equilibrium_system.h"
#include "dem/solver/fire_relaxation.h"
#include "dem/solver/lbfgs_relaxation.h"
#include "dem/solver/newton_krylov.h"
#include "dem/solver/residual_norms.h"
#include "dem/solver/solver_work.h"
#include "dem/solver/steihaug_cg.h"
#include "dem/solver/trial_step.h"
#include "dem/solver/trust_radius.h"

#include <Eigen/Core>

#include <iosfwd>

namespace compax::dem
{
  /// Tolerances and limits of the equilibrium solver.
  struct EquilibriumOptions
  {
    /// Converged when every particle's net force is below this fraction of
    /// the mean contact force [-].
    double force_tolerance = 1e-6;
    /// ... or below this absolute force [N]. A bed that unloads towards a
    /// stress-free state (a thin compact whose punch comes free) has a
    /// vanishing mean contact force, and the relative criterion alone then
    /// asks for round-off; 0: none.
    double force_floor = 0.0;
    /// ... and the last step moved no particle farther than this fraction of
    /// the mean radius [-].
    double step_tolerance = 1e-4;
    /// Newton iterations before the solve is declared failed.
    int max_iterations = 200;
    /// Largest relative tolerance (forcing term) of the inexact linear
    /// solves; the forcing term is min(max_forcing, sqrt(|F| / |F_0|)) [-].
    /// A loose first solve after a load increment (0.5) gives poor steps
    /// that drive the iterate into indefinite regions.
    double max_forcing = 0.1;
    /// Floor of the eigenvalues of the block-Jacobi preconditioner, which
    /// is also the trust-region norm, relative to the mean diagonal
    /// stiffness [-]. Particles with few contacts (near rattlers) are soft
    /// in some directions; the floor keeps their weight in the norm, so that
    /// a step along their negative curvature stays as short as the others.
    double preconditioner_floor = 1e-3;
    /// Shorten the step of every particle that would close a gap to a
    /// contact the quadratic model does not see (virgin, apart) by more
    /// than that gap plus the mean overlap of the loaded contacts: the
    /// model has no stiffness there, and such steps (floppy particles
    /// running into neighbours) are otherwise rejected over and over. Also
    /// caps every particle's step at a quarter of the Verlet skin, particle
    /// by particle, instead of shrinking the trust region of the whole bed
    /// for the sake of one particle.
    bool limit_to_gaps = true;
    /// Conjugate-gradient iterations per Newton iteration.
    int max_cg_iterations = 2000;
    /// Initial and largest trust-region radius as fractions of
    /// R_mean sqrt(N), i.e. of a step that moves every particle by about
    /// the mean radius [-].
    double initial_radius = 0.05;
    double max_radius     = 0.5;
    /// Newton iterations without a tenfold drop of the residual after which
    /// the solver relaxes the bed (stall_relaxation) before going on.
    int stall_iterations = 8;
    /// The minimiser that relaxes a stalled Newton iteration.
    enum class StallRelaxation
    {
      /// FIRE (Bitzek et al. 2006).
      fire,
      /// L-BFGS with the diagonal stiffness as its seed: a fifth faster on
      /// the jammed compaction and unloading of the 6512-sphere die, slower
      /// on its ejection (doc/benchmarks.md, stop 51).
      lbfgs
    };
    StallRelaxation stall_relaxation = StallRelaxation::fire;
    /// Iterations (FIRE) or residual evaluations (L-BFGS) per fallback.
    int fire_iterations = 5000;
    /// Relative residual (max_i |F_i| / mean contact force) at which a
    /// fallback relaxation hands back to Newton [-].
    double fire_tolerance = 1e-3;
    /// The model Hessian of the trust-region subproblem. false: the
    /// assembled K; true: the system's matrix-free operator where it has
    /// one (EquilibriumSystem::apply_model_hessian: the frozen-angle
    /// Jacobian of the nonlocal formulation, with the amplification
    /// (I - D C)^-1 that its approximate K lacks), K then preconditions.
    bool matrix_free_model = false;
    /// Start every solve at initial_radius instead of the radius the last
    /// solve ended with.
    bool reset_radius = false;
    /// Below this relative residual Newton-Krylov on the exact Jacobian
    /// (NewtonKrylov) finishes the solve: quadratic convergence where the
    /// assembled K only approximates dF/dx (the nonlocal formulation); if
    /// it fails, the trust region goes on from where it stopped. 0: never
    /// [-].
    double krylov_switch = 0.0;
    /// Target of the FIRE fallback. false: fire_tolerance; true: two
    /// decades below the current residual, within [force_tolerance,
    /// fire_tolerance] (FIRE converges for a field that is not a gradient,
    /// where the trust region's work measure can cycle).
    bool fire_below_residual = false;
    /// A step that predicts no decrease while the bed is out of balance.
    enum class LostDecrease
    {
      /// A step clipped by limit_to_gaps is shortened uniformly instead
      /// (a Steihaug step is a descent direction); if that predicts no
      /// decrease either, the solve stops (not converged).
      shorten_then_stop,
      /// The trust radius is quartered and the subproblem solved again.
      shrink_radius
    };
    LostDecrease lost_decrease = LostDecrease::shorten_then_stop;
    /// After a FIRE fallback, test convergence and build the next step
    /// from the relaxed state's residual; false: the next iteration tests
    /// it, and the step after the fallback keeps the forcing term of the
    /// residual before it.
    bool test_after_fallback = true;
    /// Where to write one line per Newton iteration (residual, trust
    /// radius, CG iterations, ratio of actual to predicted decrease), for
    /// diagnosing convergence; null for none.
    std::ostream *trace = nullptr;
  };

  /**
   * The trust region for the nonlocal formulation (Gonzalez & Cuitino
   * 2012; NonlocalBedSystem), whose model Hessian is the matrix-free
   * frozen-angle Jacobian and whose forces are not a gradient: more
   * iterations with shorter CG solves, a fresh radius per load step, the
   * exact-Jacobian Newton-Krylov below a relative residual of 1e-2, FIRE
   * after 40 iterations without a tenfold drop.
   */
  inline EquilibriumOptions
  nonlocal_equilibrium_options()
  {
    EquilibriumOptions o;
    o.matrix_free_model   = true;
    o.max_iterations      = 300;
    o.max_cg_iterations   = 400;
    o.stall_iterations    = 40;
    o.reset_radius        = true;
    o.krylov_switch       = 1e-2;
    o.fire_below_residual = true;
    o.lost_decrease       = EquilibriumOptions::LostDecrease::shrink_radius;
    o.test_after_fallback = false;
    return o;
  }

  /// Outcome of one equilibrium solve.
  struct EquilibriumResult
  {
    bool converged      = false;
    int  rejected_steps = 0;
    /// max_i |F_i| / mean contact force at the end [-].
    double      relative_residual = 0.0;
    ContactSums sums;
    /// Iterations, assemblies and the time spent in them.
    SolverWork work;
    /// Iterations of the Newton-Krylov finish (krylov_switch).
    int krylov_iterations = 0;
  };

  /// Assembles F and K of @p system at its coordinates into @p result's
  /// contact sums, counting and timing the assembly in its work record.
  void
  assemble_timed(EquilibriumSystem &system,
                 Eigen::VectorXd   &F,
                 BlockSparseMatrix &K,
                 EquilibriumResult &result);

  /// The equilibrium test of both trust-region solvers: F balanced to the
  /// relative force tolerance, or every net force below the force floor.
  bool
  forces_balanced(const EquilibriumResult  &result,
                  const Eigen::VectorXd    &F,
                  const EquilibriumOptions &options);

  /**
   * Static equilibrium of a bed at fixed walls and fixed internal variables
   * (Gonzalez 2018, Eq. 12 and Algorithm 1, lines 3-12): a trust-region
   * Newton method on the bed's stored energy, whose gradient is the
   * residual F and whose Hessian is K. Each step solves the trust-region
   * subproblem with Steihaug-Toint conjugate gradients (block-Jacobi
   * preconditioned, inexact with forcing term min(max_forcing,
   * sqrt(|F|/|F_0|))),
   * which handles indefinite K (geometric and softening terms) and the
   * singular directions of rattlers. The energy change of a step is
   * measured by the trapezoidal rule -(F(x) + F(x+s)).s/2, exact for a
   * quadratic energy, so no energy needs to be evaluated.
   *
   * The model Hessian is the assembled K, or with
   * EquilibriumOptions::matrix_free_model the system's matrix-free
   * operator (the nonlocal formulation). With
   * EquilibriumOptions::krylov_switch, Newton-Krylov on the exact Jacobian
   * finishes near equilibrium. One solver for every system: local laws,
   * the nonlocal layer, die beds and periodic cells.
   */
  class TrustRegionNewton
  {
  public:
    explicit TrustRegionNewton(EquilibriumOptions  options = {},
                               NewtonKrylovOptions krylov  = {});

    /// Moves bed.particles to equilibrium; bed.walls and histories fixed.
    EquilibriumResult
    solve(Bed &bed, const ContactModel &model);

    /// Moves the particles of any system to equilibrium.
    EquilibriumResult
    solve(EquilibriumSystem &system);

    const EquilibriumOptions &
    options() const
    {
      return opts;
    }

    /// Forgets the trust radius carried over from the last solve, so that
    /// the next solve depends on its system alone (reproducible trials).
    void
    reset()
    {
      radius.forget();
    }

    /// The stiffness at the last evaluated state.
    const BlockSparseMatrix &
    stiffness() const
    {
      return K;
    }

  private:
    EquilibriumOptions        opts;
    ContactAssembler          assembler;
    BlockSparseMatrix         K;
    BlockJacobiPreconditioner M;
    SteihaugCG                cg;
    NewtonKrylov              krylov;
    FireRelaxation            fire;
    LbfgsRelaxation           lbfgs;
    TrialStep                 trial;
    Eigen::VectorXd           F, s, s_full, Ks, factor;
    TrustRadius               radius;

    /// Hv = H v with the subproblem's model Hessian (K, or the system's
    /// operator with EquilibriumOptions::matrix_free_model).
    void
    apply_model_hessian(EquilibriumSystem     &system,
                        const Eigen::VectorXd &v,
                        Eigen::VectorXd       &Hv) const;
  };

} // namespace compax::dem
