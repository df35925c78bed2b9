#pragma once

#include <vector>

namespace compax::coupling
{
  /// Stress invariants p = -tr(sigma)/3 (compression positive) and
  /// q = sqrt(3 J2) [Pa].
  struct StressInvariants
  {
    double p;
    double q;
  };

  /// Drucker-Prager shear failure line q = d + p tan(beta).
  struct ShearLine
  {
    double cohesion;           ///< d [Pa]
    double tan_friction_angle; ///< tan(beta) [-]
  };

  /// The shear line through two failure states (different p) [Pa].
  ShearLine
  shear_line_through(const StressInvariants &a, const StressInvariants &b);

  /// Cap of a Drucker-Prager Cap model (fem/drucker_prager_cap.h):
  /// F_c = sqrt((p - p_a)^2 + (R q)^2) - R (d + p_a tan beta),
  /// p_a = (p_b - R d) / (1 + R tan beta).
  struct CapParameters
  {
    double eccentricity; ///< R [-]
    double cap_pressure; ///< hydrostatic yield pressure p_b [Pa]
    double cap_origin;   ///< p_a [Pa]
  };

  /**
   * The cap that passes through a state (p, q) reached in uniaxial-strain
   * (die) compaction with an associated flow normal that points along
   * uniaxial plastic straining: d eps_q / d eps_v = 2/3 for a plastic
   * strain increment (0, 0, d eps_z), hence (dF/dq)/(dF/dp) =
   * R^2 q / (p - p_a) = 2/3 and p - p_a = 1.5 R^2 q. With F_c = 0 this
   * leaves q sqrt(1 + 2.25 R^2) = d + (p - 1.5 R^2 q) tan beta, one
   * equation for R (solved by bisection; its left minus right side grows
   * monotonically in R), after which p_a and p_b follow. (The elastic part
   * of the lateral strain is neglected, as die-compaction calibrations of
   * the DPC (Han et al. 2008) do.) Throws std::domain_error when no R > 0
   * fits (the state lies on or above the shear line).
   */
  CapParameters
  cap_through_uniaxial_state(const StressInvariants &state,
                             const ShearLine        &line);

  /**
   * Tabulated cap pressures for a DPC table whose rows sit at the
   * (increasing) densities @p rows while each fitted cap pressure
   * @p cap_pressure[k] belongs to the plastic density @p plastic_density[k]
   * (the DPC hardens its cap with the plastic density, which at a loaded
   * state lies below the total density by the elastic volumetric strain).
   * Returns the values y_k at the rows such that the table's rule
   * (fem::DpcTable::cap_pressure: linear in log p_b between rows, linear
   * extrapolation of log p_b outside) gives cap_pressure[k] at
   * plastic_density[k] for every k, by solving that linear system in
   * log p_b. Throws std::domain_error if it is singular (two plastic
   * densities in one interval of the rows' extrapolation).
   */
  std::vector<double>
  cap_pressures_at_rows(const std::vector<double> &rows,
                        const std::vector<double> &plastic_density,
                        const std::vector<double> &cap_pressure);
} // namespace compax::coupling
