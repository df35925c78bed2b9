#pragma once

#include "dem/rve/cell_steps.h"
#include "dem/rve/periodic_assembler.h"
#include "dem/rve/periodic_bed.h"
#include "dem/solver/fire_relaxation.h"
#include "dem/solver/lbfgs_relaxation.h"
#include "dem/solver/load_stepper.h"
#include "dem/solver/trust_region_newton.h"
#include "dem/solver/unjammed_equilibrium.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// How an RVE below its jamming pressure is driven (the die's
  /// Protocol/Consolidation, see DieProtocol::consolidate).
  enum class RveConsolidation
  {
    /**
     * The bonded path (Gonzalez 2018, Algorithm 1, as the die follows it):
     * an unjammed sub-step is relaxed by FIRE at fixed internal variables
     * and that relaxed state is a converged state, to which Eq. (13) is
     * applied (no plastic radius, no bridge at contacts whose force is
     * below the force resolution). Jamming is sticky: once a converged
     * state carried the jamming pressure, every later sub-step (unloading
     * included) is solved by Newton, whatever its pressure.
     */
    none,
    /**
     * The former behaviour, kept for comparison: a sub-step that starts
     * below the jamming pressure relaxes by FIRE with frozen histories (the
     * relaxed state is not committed), every forces resolved; not sticky.
     */
    frozen_history
  };

  /// Settings of an RVE driven along a strain path.
  struct RveLoadingOptions
  {
    EquilibriumOptions  equilibrium;
    LoadSteppingOptions stepping;
    /// Mean compressive stress -tr(sigma)/3 below which the cell counts as
    /// not jammed [Pa]: its steps relax by FIRE (Newton has no stiffness
    /// along the mechanisms of a loose cell); see RveConsolidation.
    double jamming_pressure = 0.5e6;
    /// What happens below the jamming pressure.
    RveConsolidation consolidation = RveConsolidation::none;
    /// Bonded path: the converged state of an unjammed sub-step, as
    /// LoadSteppingOptions::unjammed_equilibrium in the die: the relaxed
    /// cell (relaxation; its test, net forces below the force resolution,
    /// accepts force chains that a balanced loose cell does not carry),
    /// the trust-region Newton from it (relaxation_then_newton; a failed
    /// Newton cuts the sub-step back, a relaxation that does not converge
    /// hands its state to Newton too), or the relaxation run to the
    /// equilibrium options' force tolerance, or below force_tolerance times
    /// a particle's share of the jamming pressure, within
    /// balanced_iterations (balanced_relaxation; balanced_lbfgs, the
    /// default, minimises by L-BFGS instead of FIRE). least_squares is the
    /// die's only: the constructor refuses it.
    UnjammedEquilibrium unjammed_equilibrium
      = UnjammedEquilibrium::balanced_lbfgs;
    /// FIRE iterations, or L-BFGS residual evaluations, allowed per
    /// balanced relaxation ...
    int balanced_iterations = 1000000;
    /// ... which gives up, and cuts the sub-step back, once this many pass
    /// without halving its distance to balance (as the die's,
    /// LoadSteppingOptions::balanced_stall_window).
    int balanced_stall_window = 200000;
    /// FIRE iterations allowed per unjammed sub-step.
    int fire_iterations = 20000;
    /// Relative residual an unjammed sub-step relaxes to [-] ...
    double fire_tolerance = 1e-2;
    /// ... or a net force below this fraction of the jamming pressure times
    /// pi R_mean^2 (forces negligible in absolute terms) [-]. On the bonded
    /// path this force is also the force resolution of Eq. (13) (the die's
    /// DieCompaction::force_resolution()).
    double force_floor_fraction = 1e-2;
    /// Bonded path: false, Eq. (13) applies at every positive overlap of a
    /// converged state, however small its force (the die's
    /// DieProtocol::resolved_history).
    bool resolved_history = true;
  };

  /// Outcome of one macroscopic step (possibly several sub-steps).
  struct RveStepResult
  {
    bool converged = false;
    /// Whether the cell counted as jammed at the last sub-step (bonded
    /// path: at its end, sticky; frozen history: at its start).
    bool jammed = true;
    /// Whether the last converged sub-step was an unjammed FIRE relaxation
    /// (balanced to fire_tolerance or the force resolution; committed with
    /// Eq. 13 on the bonded path, not committed with frozen histories)
    /// rather than a Newton solve to the equilibrium options.
    bool relaxed  = false;
    int  substeps = 0;
    int  cutbacks = 0;
    /// Newton and conjugate-gradient iterations (jammed sub-steps).
    int iterations    = 0;
    int cg_iterations = 0;
    /// FIRE iterations (unjammed sub-steps).
    int         relaxation_iterations = 0;
    BondChanges bonds;
    /// max_i |F_i| / mean contact force at the end [-].
    double relative_residual = 0.0;
  };

  /**
   * Drives a periodic cell to a prescribed macroscopic deformation
   * gradient in sub-steps. Each sub-step maps the particles affinely with
   * the cell (the predictor), solves for the fluctuations by the die's
   * trust-region Newton at the fixed lattice, and on convergence updates
   * the internal variables (Eq. 13); a failed sub-step is undone and
   * halved, as LoadStepper does for punches (every a_p, a_B of the cell
   * restored). Below the jamming pressure the sub-step relaxes by FIRE
   * instead, as RveLoadingOptions::consolidation says: on the bonded path
   * exactly as LoadStepper's unjammed sub-steps (relaxed state committed
   * with Eq. 13 at the force resolution; a relaxation that ends at the
   * jamming pressure is finished by Newton; one that does not converge
   * while the cell stays unjammed cuts the sub-step back; jammed once,
   * jammed for good).
   */
  class RveLoading : public CellSteps<RveLoading, RveStepResult>
  {
  public:
    RveLoading(const ContactModel &model, RveLoadingOptions options = {});

    /// Deforms the cell to H = F_target H_0.
    RveStepResult
    deform_to(PeriodicBed &bed, const Eigen::Matrix3d &F_target);

    const RveLoadingOptions &
    options() const
    {
      return opts;
    }

    /// Whether the cell counts as jammed: on the bonded path, whether some
    /// converged state so far carried the jamming pressure (an object that
    /// has not converged a sub-step yet asks the cell); with frozen
    /// histories, whether the cell carries it now.
    bool
    jammed(const PeriodicBed &bed);

    /// Declares the cell jammed for good (bonded path), e.g. a probe or a
    /// resumed run from a state of a path that has jammed: Newton for every
    /// sub-step from now on.
    void
    set_jammed()
    {
      loose = 0;
    }

    /// Force resolution of Eq. (13) and of the unjammed relaxations of the
    /// cell: force_floor_fraction p_jam pi R_mean^2 [N].
    double
    force_resolution(const PeriodicBed &bed) const;

    /// Net force below which a balanced relaxation (or Newton) counts a
    /// cell as balanced [N]: the equilibrium options' force floor, at least
    /// force_tolerance times a particle's share pi R^2 of the jamming
    /// pressure (so that a loose cell whose contacts open is balanced).
    double
    balanced_force_floor(const PeriodicBed &bed) const;

  private:
    friend CellSteps<RveLoading, RveStepResult>;

    /// One sub-step to F; true if converged (state advanced).
    bool
    substep(PeriodicBed &bed, const Eigen::Matrix3d &F, RveStepResult &total);

    /// Eq. (13) on a converged sub-step at forces resolved to `resolution`
    /// [N]; on the bonded path remembers whether the cell, at mean pressure
    /// `pressure` [Pa] before the update, is still unjammed.
    void
    commit(PeriodicBed   &bed,
           double         pressure,
           double         resolution,
           RveStepResult &total);

    const ContactModel &model;
    RveLoadingOptions   opts;
    PeriodicAssembler   assembler;
    TrustRegionNewton   newton;
    FireRelaxation      fire;
    LbfgsRelaxation     lbfgs;
    PeriodicBed         saved;
    double              fraction = 1.0;
    /// Bonded path: whether the cell is still unjammed; -1: not known yet.
    int loose = -1;
  };

  /// Logarithmic (Hencky) strain ln(V) of F = V R, 1/2 ln(F F^T) [-].
  Eigen::Matrix3d
  logarithmic_strain(const Eigen::Matrix3d &F);

  /// Mean compressive stress -tr(sigma)/3 of a cell [Pa].
  double
  mean_pressure(const PeriodicBed &bed);
} // namespace compax::dem
