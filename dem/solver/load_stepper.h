#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/fire_relaxation.h"
#include "dem/solver/lbfgs_relaxation.h"
#include "dem/solver/least_squares_trust_region.h"
#include "dem/solver/trust_region_newton.h"
#include "dem/solver/unjammed_equilibrium.h"

namespace compax::dem
{
  /// Limits of the adaptive load stepping.
  struct LoadSteppingOptions
  {
    /// Smallest sub-step as a fraction of the requested increment [-].
    double min_fraction = 1.0 / 1024.0;
    /// Growth factor of the sub-step after a success [-].
    double growth = 1.5;
    /// Extrapolate the last converged sub-step (else affine heights).
    bool secant_predictor = true;
    /**
     * ... also while the bed is unjammed (jamming_pressure). There the
     * equilibrium is not unique (every overlap-free arrangement is one), so
     * the predictor decides which one the minimiser finds: the secant
     * predictor moves every particle on by the rearrangement of the last
     * sub-step, like a momentum, and the affine one starts each sub-step
     * from the punch's uniform strain, as the RVE's cell mapping does.
     * Measured (doc/loose_regime.md): the secant predictor jams a
     * 1500-sphere Material 1 bed 0.005 later and costs 17 % more time.
     */
    bool secant_predictor_unjammed = true;
    /**
     * Punch pressure below which the bed counts as unjammed [Pa]; 0: none
     * (every sub-step is solved by the trust-region Newton). While the bed
     * is unjammed (the punches of every converged state so far carried
     * less; once jammed, it stays jammed for unloading and ejection),
     * a sub-step is relaxed by FIRE at fixed internal variables to
     * unjammed_tolerance times the mean contact force, or until every net
     * force is below force_resolution: below jamming Newton has no
     * stiffness along the bed's mechanisms, and its steps stay on the
     * scale of the overlaps while the particles rearrange. The relaxed
     * state is the sub-step's converged state (Eq. 13 is applied to it)
     * unless its punches carry the jamming pressure; then Newton continues
     * from it. A relaxation that does not converge in unjammed_iterations
     * while the bed stays unjammed cuts the sub-step back.
     */
    double jamming_pressure = 0.0;
    /// Relative residual of an unjammed relaxation [-].
    double unjammed_tolerance = 1e-2;
    /**
     * The converged state of an unjammed sub-step (see
     * UnjammedEquilibrium):
     * - relaxation: the relaxed state (unjammed_tolerance or the force
     *   resolution);
     * - relaxation_then_newton: a trust-region Newton solve to
     *   EquilibriumOptions' tolerances continues from the relaxed state,
     *   converged or not (a relaxation that did not converge only has to
     *   remove the large rearrangements), and its solution is the
     *   sub-step's state; a Newton solve that fails cuts the sub-step back;
     * - balanced_relaxation: the relaxation runs to EquilibriumOptions'
     *   force tolerance or force floor, for as long as it keeps
     *   approaching them (balanced_stall_window) and at most
     *   balanced_iterations; one that does not get there cuts the sub-step
     *   back;
     * - least_squares: no relaxation; LeastSquaresTrustRegion (Algorithm
     *   1 as printed) to its step tolerance, a state that need not be
     *   balanced; one that does not converge cuts the sub-step back.
     */
    UnjammedEquilibrium unjammed_equilibrium = UnjammedEquilibrium::relaxation;
    /// FIRE iterations allowed per unjammed relaxation.
    int unjammed_iterations = 50000;
    /// FIRE iterations (L-BFGS residual evaluations) allowed per balanced
    /// relaxation: near the jamming onset the slowest mode of the bed
    /// softens, and a 6512-sphere die step there took up to 3.6e5
    /// evaluations (doc/benchmarks.md).
    int balanced_iterations = 1000000;
    /// A balanced relaxation that has not halved its distance to balance
    /// (max_i |F_i| over the force it must fall below) within this many
    /// evaluations gives up, and the sub-step is cut back
    /// (Relaxation::give_up_when_stalled).
    int balanced_stall_window = 200000;
    /**
     * Force resolution of the study [N]: Eq. (13) grows no plastic radius
     * (and forms no bridge) at a contact whose force is below it (see
     * update_history()), and an unjammed relaxation whose net forces are
     * all below it has converged. 0: every force is resolved.
     */
    double force_resolution = 0.0;
    /// false: Eq. (13) grows a_p at every positive overlap of a converged
    /// state, however small its force (force_resolution then only ends
    /// unjammed relaxations).
    bool resolved_history = true;
    /**
     * Where Newton fails on a sub-step that opens the punch gap of a jammed
     * bed: true, the balanced relaxation takes that sub-step at once
     * (relax_coming_apart()); false, the sub-step is cut back, and only the
     * smallest sub-step goes to the relaxation. Both stop at the same
     * tolerances, and may find different balanced states of a compact that
     * comes apart. Measured (doc/benchmarks.md): Gonzalez 2018's Sec. 5
     * studies of both materials are the same to the bit either way; the
     * Walton-Braun bed of the peer comparison unloads in half the time.
     */
    bool relax_opening_at_first_failure = true;
  };

  /// Outcome of one load step (possibly several sub-steps).
  struct LoadStepResult
  {
    bool              converged = false;
    int               substeps  = 0;
    int               cutbacks  = 0;
    BondChanges       bonds;
    EquilibriumResult last;
    /// The work of every sub-step, relaxations included.
    SolverWork work;
    /// Whether the last converged sub-step was an unjammed relaxation
    /// rather than a Newton solve (balanced to
    /// LoadSteppingOptions::unjammed_tolerance or the force resolution, or
    /// with balanced_relaxation to EquilibriumOptions' tolerances).
    bool relaxed = false;
  };

  /**
   * Moves the walls of a bed from their current position to a target in
   * sub-steps, each ending in static equilibrium followed by the history
   * update of Eq. (13) (Algorithm 1, line 14). A sub-step whose equilibrium
   * fails is undone (positions, walls and contacts restored) and halved;
   * after a success the sub-step grows again.
   *
   * Predictor: when the walls move on in the direction of the last
   * converged sub-step, the particles are moved by that sub-step's
   * displacements scaled to the new wall increment (secant predictor; it
   * carries the non-affine part of the response, which halves the Newton
   * iterations); otherwise the heights are mapped affinely from the old to
   * the new punch gap.
   */
  class LoadStepper
  {
  public:
    LoadStepper(const ContactModel &model,
                EquilibriumOptions  equilibrium = {},
                LoadSteppingOptions stepping    = {});

    /// Drives bed.walls to `target` (punch heights, die diameter and
    /// presence).
    LoadStepResult
    advance(Bed &bed, const DieWalls &target);

    /// Equilibrium at the current walls, then history update; an unjammed
    /// bed is relaxed as in advance() (a rerun of a loose saved state).
    LoadStepResult
    equilibrate(Bed &bed);

    TrustRegionNewton &
    solver()
    {
      return newton;
    }

    /// Reports the progress of the unjammed relaxations and of the last
    /// resort (FIRE or L-BFGS) every @p interval seconds [s] of a
    /// relaxation; an empty report reports nothing.
    void
    report_relaxations(const RelaxationReport &report, const double interval)
    {
      fire.report_progress(report, interval);
      lbfgs.report_progress(report, interval);
    }

    /// Forgets the last increment (the next sub-step uses the affine
    /// predictor), e.g. after the bed was changed outside the stepper.
    void
    reset_predictor()
    {
      have_increment = false;
    }

    /// Whether the punches of every converged state so far carried less
    /// than the jamming pressure (a stepper that has not converged a
    /// sub-step yet asks the bed).
    bool
    unjammed(Bed &bed);

  private:
    /// Whether the punches of a bed with these sums carry less than the
    /// jamming pressure.
    bool
    below_jamming(const Bed &bed, const ContactSums &sums) const;

    /// What relax_unjammed() leaves to do.
    enum class UnjammedStep
    {
      relaxed, ///< the relaxed bed is the sub-step's equilibrium
      newton,  ///< the bed is (or became) jammed: solve by Newton
      failed   ///< unjammed, but the relaxation did not converge: cut back
    };

    /// The relaxation of the Unjammed equilibrium option at the current
    /// walls, its time and iterations added to `total`.
    FireResult
    relax(Bed &bed, LoadStepResult &total);

    /// `total.last` of a converged relaxation.
    EquilibriumResult
    relaxed_result(const FireResult &f, LoadStepResult &total);

    /// Relaxes an unjammed sub-step (see LoadSteppingOptions). A
    /// relaxation that does not converge while the bed stays unjammed
    /// fails the sub-step rather than handing Newton a bed without
    /// stiffness along its mechanisms (a smaller sub-step starts closer
    /// to equilibrium).
    UnjammedStep
    relax_unjammed(Bed &bed, LoadStepResult &total);

    /// The equilibrium of one sub-step at the current walls: the unjammed
    /// relaxation, else Newton; not converged when either fails.
    EquilibriumResult
    solve_substep(Bed &bed, LoadStepResult &total);

    /**
     * The sub-step to walls `next` from `saved` once more, by the balanced
     * relaxation, after Newton failed on it (at once, or only on the
     * smallest sub-step: relax_opening_at_first_failure): the last resort
     * before the step fails, for a jammed bed whose punch gap opens (a
     * compact without bridges coming apart on unloading, whose floppy
     * modes Newton cannot balance). Converged only if the relaxation
     * balances it to the tolerances of Newton (a balanced Unjammed
     * equilibrium only); a run that converges without it is unchanged.
     * Once it has balanced a sub-step, the following ones that open the
     * gap further start with it (Newton would fail there again).
     */
    EquilibriumResult
    relax_coming_apart(Bed &bed, const DieWalls &next, LoadStepResult &total);

    /// Eq. (13) on a converged sub-step; remembers whether it is unjammed.
    void
    commit(Bed &bed, const ContactSums &sums, LoadStepResult &total);

    /// Moves the particles to the predicted positions for walls `next`.
    void
    predict(Bed &bed, const DieWalls &next);

    const ContactModel     &model;
    TrustRegionNewton       newton;
    LeastSquaresTrustRegion least_squares;
    FireRelaxation          fire;
    LbfgsRelaxation         lbfgs;
    LoadSteppingOptions     stepping;
    double                  fraction = 1.0;
    /// Whether the bed is still unjammed; -1: not known yet.
    int loose = -1;
    /// Whether the last sub-step was relax_coming_apart()'s: the next ones
    /// that open the punch gap further go to it without Newton.
    bool coming_apart = false;
    Bed  saved;
    // Secant predictor: the last converged sub-step's displacements and
    // wall increments (lower punch, upper punch, diameter).
    Eigen::VectorXd last_increment;
    double          last_delta[3]    = {0.0, 0.0, 0.0};
    bool            last_die_present = true;
    bool            have_increment   = false;
  };

  /// Walls between a and b at fraction t in [0, 1] (die presence from b).
  DieWalls
  interpolate(const DieWalls &a, const DieWalls &b, double t);
} // namespace compax::dem
