#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/fire_relaxation.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// Parameters of the consolidation of a loose bed up to jamming.
  struct ConsolidationOptions
  {
    /// Upper-punch pressure at which the bed counts as jammed [Pa]. It
    /// should be small against the compaction pressures of interest (the
    /// plastic work done below it is neglected) but large enough that the
    /// contact network is rigid (Newton then converges); 0.1 - 1 % of
    /// kappa works for Material 1.
    double jamming_pressure = 0.5e6;
    /// First axial strain of one punch increment [-]. It grows by 1.5 while
    /// the relaxed bed carries (almost) no force; once the punch carries
    /// more than 1 % of the jamming pressure it is set by the secant of the
    /// last two increments to aim at the jamming pressure (overshoot 20 %);
    /// a relaxation that fails is undone and retried with a quarter of the
    /// increment; below min_strain_increment consolidation fails.
    double initial_strain_increment = 2e-3;
    double max_strain_increment     = 1e-2;
    double min_strain_increment     = 5e-5;
    /// A relaxation has converged when max_i |F_i| <= relative_tolerance
    /// times the mean contact force, or when every |F_i| is below the
    /// force floor (below).
    double relative_tolerance = 1e-2;
    /// Forces below this fraction of p_jam pi R^2 are negligible [-]: a bed
    /// whose out-of-balance forces are all smaller counts as relaxed.
    double force_floor_fraction = 1e-2;
    /// Relaxation iterations per increment before it counts as failed.
    int max_relaxation_iterations = 50000;

    /// Punch pressure a study resolves [Pa]: force_floor_fraction times the
    /// jamming pressure (5 kPa by default). Loose states carry less, so a
    /// relative difference against them says nothing.
    double
    pressure_resolution() const
    {
      return force_floor_fraction * jamming_pressure;
    }
  };

  /// Outcome of a relaxation at fixed walls.
  struct RelaxationResult
  {
    bool        converged  = false;
    int         iterations = 0;
    ContactSums sums;
    /// max_i |F_i| / mean contact force (0 if no force) [-].
    double relative_residual = 0.0;
  };

  /// Outcome of a consolidation.
  struct ConsolidationResult
  {
    /// The punch pressure reached the jamming pressure after relaxation.
    bool jammed = false;
    /// The relaxation of some increment failed (bed left as it was after
    /// the last converged increment).
    bool failed     = false;
    int  increments = 0;
    /// Relaxation iterations, residual evaluations among them with the
    /// stiffness (masses) [-].
    int         iterations = 0;
    int         assemblies = 0;
    double      seconds    = 0.0;
    ContactSums sums;
    double      relative_residual = 0.0;
  };

  /**
   * Consolidation of a loose frictionless bed (e.g. a ballistic deposit at
   * rho ~ 0.45) up to jamming, before the static load steps.
   *
   * Below jamming the bed's stiffness is singular along mechanisms and its
   * equilibria are all force-free: Newton steps cannot rearrange the
   * particles (they are confined to the overlap scale). Forces, and hence
   * plastic deformation and bonding, are negligible there, so the upper
   * punch advances in small axial-strain increments (affine predictor of
   * the particle heights) and after each increment the bed is relaxed at
   * fixed walls and fixed internal variables (all virgin contacts follow
   * the plastic loading curve reversibly) by FIRE (FireRelaxation). The
   * consolidation stops
   * when the relaxed bed carries the jamming pressure on the upper punch;
   * the caller then solves the static equilibrium with Newton and updates
   * the internal variables (Eq. 13) at that state.
   *
   * Hot loops allocate nothing after the first increment.
   */
  class Consolidation
  {
  public:
    explicit Consolidation(ConsolidationOptions options = {});

    /**
     * Advances the upper punch until the bed jams or its in-die relative
     * density reaches `max_density`, whichever comes first.
     */
    ConsolidationResult
    run(Bed &bed, const ContactModel &model, double max_density);

    /// FIRE relaxation of the bed at its current walls.
    RelaxationResult
    relax(Bed &bed, const ContactModel &model);

    const ConsolidationOptions &
    options() const
    {
      return opts;
    }

  private:
    ConsolidationOptions opts;
    FireRelaxation       fire;
    double               strain_increment = 0.0;
    double               force_floor      = 0.0;
    int                  assemblies       = 0;
  };
} // namespace compax::dem
