#pragma once

#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/rve/cell_steps.h"
#include "dem/rve/periodic_bed.h"
#include "dem/rve/rve_loading.h"
#include "dem/solver/substepping.h"
#include "dem/solver/trust_region_newton.h"

#include <Eigen/Core>

#include <vector>

namespace compax::dem
{
  /// Settings of a NonlocalRveLoading.
  struct NonlocalRveOptions
  {
    /// Elastic constants per material number of the cell's particles.
    std::vector<ElasticMaterial> materials;
    /// Nonlocal formulation (Gonzalez & Cuitino 2012); false: Hertz.
    bool nonlocal = true;
    /// Candidate skin and Algorithm 1 tolerances (bed.nonlocal ignored).
    NonlocalBedOptions  bed;
    EquilibriumOptions  solver = nonlocal_equilibrium_options();
    NewtonKrylovOptions krylov;
    /// Mean compressive stress below which a sub-step relaxes by FIRE with
    /// Hertz contacts instead (a loose cell has no stiffness; its overlaps,
    /// hence the nonlocal terms, are negligible) [Pa]; FIRE iterations,
    /// relative residual and force floor (fraction of the jamming pressure
    /// times pi R_mean^2) of those relaxations.
    double jamming_pressure     = 0.5e6;
    int    fire_iterations      = 20000;
    double fire_tolerance       = 1e-2;
    double force_floor_fraction = 1e-2;
    /// Sub-stepping of a step.
    SubstepLimits stepping;
  };

  /**
   * Drives a periodic cell of elastic frictionless spheres (Hertz, or the
   * nonlocal contact formulation of Gonzalez & Cuitino 2012) to prescribed
   * deformation gradients: the counterpart of RveLoading for the
   * elastic laws. Each sub-step maps the particles affinely with the cell
   * (map_affinely) and solves for the fluctuations at the fixed lattice
   * with a NonlocalBedSystem on bed.particles and bed.cell (periodic
   * images) by TrustRegionNewton (nonlocal_equilibrium_options()); below the
   * jamming pressure FIRE with the local law alone relaxes the cell instead. A
   * failed sub-step is undone and halved. The law has no internal variables:
   * bed.contacts is left alone (it holds no state of this law).
   */
  class NonlocalRveLoading : public CellSteps<NonlocalRveLoading, RveStepResult>
  {
  public:
    explicit NonlocalRveLoading(NonlocalRveOptions options);

    /// Deforms the cell to H = F_target H_0.
    RveStepResult
    deform_to(PeriodicBed &bed, const Eigen::Matrix3d &F_target);

    /// Love-Weber stress of the elastic law at the cell's current state
    /// (tension positive) [Pa].
    Eigen::Matrix3d
    stress(PeriodicBed &bed) const;

    /// Mechanical coordination number 2 (loaded pairs) / N [-].
    double
    coordination(PeriodicBed &bed) const;

    const NonlocalRveOptions &
    options() const
    {
      return opts;
    }

  private:
    friend CellSteps<NonlocalRveLoading, RveStepResult>;

    bool
    substep(PeriodicBed &bed, const Eigen::Matrix3d &F, RveStepResult &total);

    /// The system of the bed's particles and walls with the options'
    /// candidate skin and tolerances and the given formulation.
    NonlocalBedSystem
    make_system(PeriodicBed &bed, bool nonlocal) const;

    NonlocalRveOptions opts;
    TrustRegionNewton  solver;
    FireRelaxation     fire;
    double             fraction = 1.0;
  };
} // namespace compax::dem
