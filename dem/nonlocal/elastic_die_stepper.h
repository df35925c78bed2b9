#pragma once

#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/solver/consolidation.h"
#include "dem/solver/load_stepper.h"
#include "dem/solver/substepping.h"
#include "dem/solver/trust_region_newton.h"

#include <vector>

namespace compax::dem
{
  /// Settings of an ElasticDieStepper.
  struct ElasticDieOptions
  {
    /// Elastic constants per material number of the bed's particles.
    std::vector<ElasticMaterial> materials;
    /// Nonlocal formulation (Gonzalez & Cuitino 2012); false: Hertz.
    bool nonlocal = true;
    /// Candidate skin, Algorithm 1 tolerances (bed.nonlocal is ignored).
    NonlocalBedOptions  bed;
    EquilibriumOptions  solver = nonlocal_equilibrium_options();
    NewtonKrylovOptions krylov;
    /// Sub-stepping of a step.
    SubstepLimits stepping;
  };

  /**
   * Load stepping of elastic frictionless spheres in the cylindrical die of
   * a Bed (the counterpart of LoadStepper for the contact formulation of
   * Gonzalez & Cuitino 2012, or Hertz): each sub-step maps the particles
   * affinely to the new walls (heights between the punches, radii with the
   * die) and solves the static equilibrium of a NonlocalBedSystem on
   * bed.particles and bed.walls with TrustRegionNewton (frozen-angle
   * Hessian, exact Newton-Krylov finish, FIRE fallback). A sub-step that
   * fails is undone and halved; after a success the sub-step grows again.
   * The law is elastic: there are no internal variables, and bed.contacts
   * is left alone (it holds no state of this law).
   */
  class ElasticDieStepper
  {
  public:
    explicit ElasticDieStepper(ElasticDieOptions options);

    /// Drives bed.walls to `target`.
    LoadStepResult
    advance(Bed &bed, const DieWalls &target);

    /// Equilibrium at the current walls.
    LoadStepResult
    equilibrate(Bed &bed);

    /**
     * Consolidation of a loose deposit up to jamming: the upper punch
     * advances in height-strain increments (options.initial_strain_
     * increment, grown up to max_strain_increment while the punch carries
     * no force) and the bed relaxes by FIRE with the local law alone (below
     * jamming the overlaps, hence the nonlocal terms, are negligible) to
     * options.relative_tolerance, until the relaxed bed carries
     * options.jamming_pressure on the upper punch or reaches max_density.
     */
    ConsolidationResult
    consolidate(Bed                        &bed,
                double                      max_density,
                const ConsolidationOptions &options);

    /// Wall forces and mean contact force at the bed's current state.
    ContactSums
    sums(Bed &bed) const;

    /// Mechanical coordination number 2 (loaded particle pairs) / N at the
    /// bed's current state [-].
    double
    coordination(Bed &bed) const;

    const ElasticDieOptions &
    options() const
    {
      return opts;
    }

  private:
    /// Equilibrium at fixed walls; adds its counts to `total`.
    bool
    solve(Bed &bed, LoadStepResult &total);

    /// The system of the bed's particles and walls with the options'
    /// candidate skin and tolerances and the given formulation.
    NonlocalBedSystem
    make_system(Bed &bed, bool nonlocal) const;

    ElasticDieOptions opts;
    TrustRegionNewton solver;
    double            fraction = 1.0;
  };
} // namespace compax::dem
