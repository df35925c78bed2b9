#pragma once

#include "apps/compare/compare_parameters.h"
#include "apps/compare/compare_studies.h"
#include "coupling/scale_comparison.h"

#include <filesystem>
#include <string>
#include <vector>

namespace compax::cli
{
  /// The columns of compare.csv, in order.
  const std::vector<std::string> &
  comparison_columns();

  /// compare.csv: comparison,relative_density,reference,value,
  /// relative_difference (missing values are empty cells).
  void
  write_comparison_csv(const std::filesystem::path                &file,
                       const std::vector<coupling::ComparisonRow> &rows);

  /// interior.csv: relative_density_die, relative_density_interior,
  /// sigma_zz_interior, sigma_rr_interior, sigma_zz_rve, sigma_xx_rve
  /// (missing values empty).
  void
  write_interior_csv(const std::filesystem::path              &file,
                     const std::vector<coupling::InteriorRow> &rows);

  /// compare.png with compare.gp in @p folder: the moduli, the punch
  /// pressures (the FE2 tablet's if @p with_fe2) and the relative
  /// differences, from the sub-studies' files and compare.csv.
  void
  plot_comparison(const std::filesystem::path   &folder,
                  const coupling::DepositedFill &fill,
                  bool                           with_fe2);

  /**
   * compare.md: the setup, how each sub-study went (@p studies: die,
   * database-mode and FE2 tablet, in that order), per comparison the rows,
   * missing values and mean and largest relative difference, and where the
   * FE2 tablet stopped.
   */
  void
  write_compare_md(const std::filesystem::path            &file,
                   const CompareSetup                     &c,
                   const coupling::DepositedFill          &fill,
                   const std::vector<const StudyStatus *> &studies,
                   const coupling::ScaleComparisonResult  &result);
} // namespace compax::cli
