#pragma once

#include "dem/rve/periodic_assembler.h"
#include "dem/rve/periodic_bed.h"
#include "dem/solver/fire_relaxation.h"
#include "dem/solver/load_stepper.h"
#include "dem/solver/trust_region_newton.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// Settings of an RVE driven along a strain path.
  struct RveLoadingOptions
  {
    EquilibriumOptions  equilibrium;
    LoadSteppingOptions stepping;
    /// Mean compressive stress -tr(sigma)/3 below which the cell counts as
    /// not jammed [Pa]: its steps relax by FIRE with frozen histories (no
    /// plastic work to speak of; Newton has no stiffness to work with).
    double jamming_pressure = 0.5e6;
    /// FIRE iterations allowed per unjammed sub-step.
    int fire_iterations = 20000;
    /// Relative residual an unjammed sub-step relaxes to [-] ...
    double fire_tolerance = 1e-2;
    /// ... or a net force below this fraction of the jamming pressure times
    /// pi R_mean^2 (forces negligible in absolute terms) [-].
    double force_floor_fraction = 1e-2;
  };

  /// Outcome of one macroscopic step (possibly several sub-steps).
  struct RveStepResult
  {
    bool converged = false;
    bool jammed    = true;
    int  substeps  = 0;
    int  cutbacks  = 0;
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
   * halved, as LoadStepper does for punches. Below the jamming pressure
   * the sub-step relaxes by FIRE instead, with histories frozen.
   */
  class RveLoading
  {
  public:
    RveLoading(const ContactModel &model, RveLoadingOptions options = {});

    /// Deforms the cell to H = F_target H_0.
    RveStepResult
    deform_to(PeriodicBed &bed, const Eigen::Matrix3d &F_target);

    /// Applies a small strain increment to the current configuration:
    /// F <- (I + eps) F, eps symmetric.
    RveStepResult
    apply_strain(PeriodicBed &bed, const Eigen::Matrix3d &strain_increment);

    /// Equilibrium at the current cell without moving it, then history
    /// update (e.g. after a restart or a change of material).
    RveStepResult
    equilibrate(PeriodicBed &bed);

    const RveLoadingOptions &
    options() const
    {
      return opts;
    }

  private:
    /// One sub-step to F; true if converged (state advanced).
    bool
    substep(PeriodicBed &bed, const Eigen::Matrix3d &F, RveStepResult &total);

    const ContactModel &model;
    RveLoadingOptions   opts;
    PeriodicAssembler   assembler;
    TrustRegionNewton   newton;
    FireRelaxation      fire;
    PeriodicBed         saved;
    double              fraction = 1.0;
  };

  /// Logarithmic (Hencky) strain ln(V) of F = V R, 1/2 ln(F F^T) [-].
  Eigen::Matrix3d
  logarithmic_strain(const Eigen::Matrix3d &F);

  /// Mean compressive stress -tr(sigma)/3 of a cell [Pa].
  double
  mean_pressure(const PeriodicBed &bed);
} // namespace compax::dem
