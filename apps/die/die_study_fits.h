#pragma once

#include "dem/analysis/curve_fits.h"
#include "dem/die/die_compaction.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace compax::cli
{
  /**
   * Fits the relations of Gonzalez 2018 Sec. 5 (Table 3) to a die study and
   * writes them as fits.csv (columns parameter,value; SI units; an empty
   * value where the study has too few points for that fit) and fits.md
   * (the same as a Markdown table with the equations and the number of
   * points behind each fit):
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
  /// The fits of the study, for plotting beside the data (empty where
  /// not determined).
  struct CompactionFits
  {
    std::optional<dem::CoordinationFit>  coordination;
    std::optional<dem::PunchPressureFit> punch_pressure;
    /// Eq. (17): elastic recovery eps_rho against rho_max.
    std::optional<dem::LinearCriticalFit> elastic_recovery;
    /// Eq. (19): residual radial pressure against rho_max.
    std::optional<dem::LinearCriticalFit> residual_pressure;
    /// Eq. (23): bonding surface after unloading against rho_min.
    std::optional<dem::LinearCriticalFit> bonding_surface;
    /// Eq. (24): tablet Young's modulus against rho_min.
    std::optional<dem::PhaniNiyogiFit> youngs_modulus;
  };

  /// Fits Eqs. (14)-(24) to the jammed compaction steps (upper punch
  /// pressure above @p pressure_resolution [Pa]) and the branches, writes
  /// fits.csv and fits.md.
  CompactionFits
  write_die_fits(const std::filesystem::path           &folder,
                 const std::vector<dem::DieRecord>     &records,
                 const std::vector<dem::BranchSummary> &branches,
                 double                                 pressure_resolution);
} // namespace compax::cli
