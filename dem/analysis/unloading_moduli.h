#pragma once

#include <vector>

namespace compax::dem
{
  /**
   * Young's modulus and Poisson's ratio of a compact from its in-die
   * unloading curve (Gonzalez 2018, Sec. 5.7): in the die the compact
   * unloads in uniaxial strain, so Hooke's law gives
   *   d sigma_z / d eps_z = M = E (1 - nu) / ((1 + nu)(1 - 2 nu)),
   *   d sigma_r / d eps_z = L = E nu / ((1 + nu)(1 - 2 nu)),
   * hence nu = L / (L + M) and E = M (1 + nu)(1 - 2 nu) / (1 - nu). The two
   * slopes are least-squares lines through the central third of the
   * unloading curve (axial pressure between 1/3 and 2/3 of its maximum).
   */
  struct UnloadingModuli
  {
    /// Young's modulus E [Pa] and Poisson's ratio nu [-].
    double youngs_modulus, poisson_ratio;
    /// The constrained modulus M and lateral modulus L [Pa].
    double axial_slope, lateral_slope;
    /// Number of points in the central third.
    unsigned int points;
  };

  /**
   * @param axial_strain compaction strain eps_z, e.g. -ln(H/H_0) or the
   *   punch displacement over the gap, any monotone measure [-]
   * @param axial_pressure punch pressure, positive in compression [Pa]
   * @param radial_pressure die-wall pressure, positive in compression [Pa]
   */
  UnloadingModuli
  moduli_from_unloading(const std::vector<double> &axial_strain,
                        const std::vector<double> &axial_pressure,
                        const std::vector<double> &radial_pressure);
} // namespace compax::dem
