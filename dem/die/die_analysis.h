#pragma once

#include "dem/solver/bed.h"

#include <vector>

namespace compax::dem
{
  /// Microstructure measures of a bed at an equilibrium state.
  struct BedMeasures
  {
    /// Mean mechanical coordination number: 2 x (particle pairs carrying a
    /// non-zero force) / N [-]; wall contacts are not counted.
    double coordination_number = 0.0;
    /// Bonding surface parameter A_b = sum a_p^2 / sum R_i^2 over the
    /// particle pairs that touch (contact radius a > 0; Gonzalez 2018
    /// Sec. 5.6: sum a_p^2 / (R^2 N_p) when monodisperse) [-]. A pair that
    /// has parted keeps its a_p as history but bonds no more, so A_b falls
    /// as contacts open on unloading and ejection (the paper's Fig. 19).
    double bonding_surface = 0.0;
    /// Particle pairs with an intact solid bridge (a_B > 0).
    std::size_t n_bonds = 0;
    /// Pairs in tension (P < 0) and in compression (P > 0).
    std::size_t n_tensile = 0, n_compressive = 0;
  };

  BedMeasures
  measure(const Bed &bed, double resolution = 0.0);

  /// Normal forces P of all particle pairs carrying a force [N] (histograms).
  std::vector<double>
  pair_forces(const Bed &bed);

  /**
   * Elastic constants of a compact confined in a rigid die from the
   * central third (in axial force) of an unloading curve (Gonzalez 2018
   * Sec. 5.7): with no radial strain, d sigma_z = M d eps_z and
   * d sigma_r = lambda d eps_z, M = E (1 - nu) / ((1 + nu)(1 - 2 nu)),
   * lambda = E nu / ((1 + nu)(1 - 2 nu)), hence
   * nu = k / (1 + k) with k = d sigma_r / d sigma_z and
   * E = M (1 + nu)(1 - 2 nu) / (1 - nu). Slopes by least squares.
   */
  struct TabletElasticity
  {
    double youngs_modulus = 0.0;
    double poisson_ratio  = 0.0;
    /// Points of the central third used in the fit.
    int n_points = 0;
  };

  /// @param strain axial strain of each point, (H - H_max) / H_max
  /// @param axial_stress punch pressure, @param radial_stress die-wall
  /// pressure of each point of one unloading branch [Pa].
  TabletElasticity
  unloading_elasticity(const std::vector<double> &strain,
                       const std::vector<double> &axial_stress,
                       const std::vector<double> &radial_stress);
} // namespace compax::dem
