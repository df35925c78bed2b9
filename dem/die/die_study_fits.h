#pragma once

#include "dem/analysis/curve_fits.h"
#include "dem/die/die_compaction.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace compax::dem
{
  /**
   * The relations of Gonzalez 2018 Sec. 5 (Table 3) fitted to a die study,
   * each empty where the study has too few points (or the fit fails):
   * - Eq. (14) Z = Z_c + Z_0 (rho - rho_c_Z)^theta over the jammed part of
   *   the compaction path;
   * - Eq. (15) punch pressure = K_p (rho - rho_c_Z)^beta_p;
   * - Eq. (17) eps_rho = eps_0 (rho_max - rho_c_eps)/(1 - rho_c_eps);
   * - Eq. (19) sigma_res = sigma_res_0 rho_max (rho_max - rho_c_e)/(1 -
   *   rho_c_e);
   * - Eq. (23) A_b = A_b0 (rho_min - rho_c_b)/(1 - rho_c_b), with A_b after
   *   unloading;
   * - Eq. (24) E = E_0 ((rho_min - rho_c_E)/(1 - rho_c_E))^n;
   * - nu_tablet, the mean Poisson's ratio of the branches (Sec. 5.7).
   */
  struct DieStudyFits
  {
    /// Eq. (14).
    std::optional<CoordinationFit> coordination;
    /// Eq. (15).
    std::optional<PunchPressureFit> punch_pressure;
    /// Eq. (17): elastic recovery eps_rho against rho_max.
    std::optional<LinearCriticalFit> elastic_recovery;
    /// Eq. (19): residual radial pressure against rho_max.
    std::optional<LinearCriticalFit> residual_pressure;
    /// Eq. (23): bonding surface after unloading against rho_min.
    std::optional<LinearCriticalFit> bonding_surface;
    /// Eq. (24): tablet Young's modulus against rho_min.
    std::optional<PhaniNiyogiFit> youngs_modulus;
    /// Sec. 5.7: the mean Poisson's ratio of the tablets [-].
    std::optional<double> poisson_ratio;
    /// The points behind the fits: jammed compaction states (Eqs. 14-15),
    /// unloading branches (Eqs. 17, 19, 23), branches whose unloading
    /// curve gave the tablet's E and nu (Eq. 24, nu_tablet).
    std::size_t jammed_states = 0, branches = 0, elastic_branches = 0;
  };

  /// Fits Eqs. (14)-(24) to the jammed compaction steps (upper punch
  /// pressure above @p pressure_resolution [Pa]) and the branches.
  DieStudyFits
  fit_die_study(const std::vector<DieRecord>     &records,
                const std::vector<BranchSummary> &branches,
                double                            pressure_resolution);
} // namespace compax::dem
