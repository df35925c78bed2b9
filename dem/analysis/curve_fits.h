#pragma once

#include <vector>

/**
 * @file
 * The semi-empirical relations of Gonzalez 2018, Sec. 5 (Eqs. 14-24 and
 * Table 3), fitted to a study's results by least squares. Linear relations
 * are solved in closed form; the power laws by Levenberg-Marquardt (Eigen's
 * unsupported LevenbergMarquardt module) started from a linearized guess.
 */

namespace compax::dem
{
  /// Eq. (14): Z = Z_c + Z_0 (rho - rho_c)^theta.
  struct CoordinationFit
  {
    double Z_c, Z_0, rho_c, theta;
    /// Root-mean-square residual of the fit.
    double rms;
    /// The optimum stands on the edge of the searched range (theta at
    /// its smallest or largest grid value, or rho_c at the largest grid
    /// distance below the data): the states do not determine a power law
    /// of the form of Eq. (14), e.g. when none lies near the onset.
    bool on_search_edge = false;
  };

  /// Eq. (15): sigma = K_p (rho - rho_c)^beta_p, rho_c given (from Eq. 14).
  struct PunchPressureFit
  {
    double K_p, beta_p, rms;
  };

  /// Eqs. (17) and (23): y = y_0 (rho - rho_c) / (1 - rho_c).
  struct LinearCriticalFit
  {
    double y_0, rho_c, rms;
  };

  /// Eq. (24): E = E_0 ((rho - rho_c) / (1 - rho_c))^n.
  struct PhaniNiyogiFit
  {
    double E_0, n, rho_c, rms;
  };

  /// Fits Eq. (14); needs at least 5 points with rho above jamming. The
  /// exponent is sought in [0.1, 2] and rho_c within 0.3 below the
  /// smallest rho (outside, the least-squares optimum is no power law);
  /// CoordinationFit::on_search_edge marks an optimum on that edge.
  CoordinationFit
  fit_coordination(const std::vector<double> &rho,
                   const std::vector<double> &Z);

  /// Fits Eq. (15) for a critical density rho_c below every rho.
  PunchPressureFit
  fit_punch_pressure(const std::vector<double> &rho,
                     const std::vector<double> &pressure,
                     double                     rho_c);

  /// Fits y = y_0 (rho - rho_c)/(1 - rho_c) (Eqs. 17, 23), a straight line
  /// y = a + b rho with y_0 = a + b and rho_c = -a/b.
  LinearCriticalFit
  fit_linear_critical(const std::vector<double> &rho,
                      const std::vector<double> &y);

  /**
   * Fits Eq. (19), sigma_res = sigma_0 rho (rho - rho_c)/(1 - rho_c): linear
   * in (rho^2, rho), so solved in closed form; returns {sigma_0, rho_c, rms}.
   */
  LinearCriticalFit
  fit_residual_pressure(const std::vector<double> &rho,
                        const std::vector<double> &pressure);

  /// Fits Eq. (24) (Phani & Niyogi).
  PhaniNiyogiFit
  fit_phani_niyogi(const std::vector<double> &rho,
                   const std::vector<double> &E);
} // namespace compax::dem
