#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/trust_region_newton.h"

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
  };

  /// Outcome of one load step (possibly several sub-steps).
  struct LoadStepResult
  {
    bool              converged     = false;
    int               substeps      = 0;
    int               cutbacks      = 0;
    int               iterations    = 0;
    int               cg_iterations = 0;
    BondChanges       bonds;
    EquilibriumResult last;
    double            assembly_seconds = 0.0;
    double            linear_seconds   = 0.0;
    int               assemblies       = 0;
    int               fire_iterations  = 0;
    double            fire_seconds     = 0.0;
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

    /// Equilibrium at the current walls, then history update.
    LoadStepResult
    equilibrate(Bed &bed);

    TrustRegionNewton &
    solver()
    {
      return newton;
    }

    /// Forgets the last increment (the next sub-step uses the affine
    /// predictor), e.g. after the bed was changed outside the stepper.
    void
    reset_predictor()
    {
      have_increment = false;
    }

  private:
    /// Moves the particles to the predicted positions for walls `next`.
    void
    predict(Bed &bed, const DieWalls &next);

    const ContactModel &model;
    TrustRegionNewton   newton;
    LoadSteppingOptions stepping;
    double              fraction = 1.0;
    Bed                 saved;
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
