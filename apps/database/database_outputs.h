#pragma once

#include "coupling/rve_database.h"
#include "coupling/rve_database_study.h"

#include <filesystem>
#include <vector>

namespace compax::cli
{
  /// database.csv: every equilibrated state with p and q.
  void
  write_database_rows(const std::filesystem::path &folder,
                      const coupling::RveDatabase &database);

  /// dpc_table.csv (the DpcTable format) and dpc_table.png.
  void
  write_dpc_table(const std::filesystem::path            &folder,
                  const std::vector<coupling::DpcFitRow> &rows);

  /// branches.csv; the plastic density and fitted cap of each branch
  /// when the fit is given (empty cells otherwise).
  void
  write_branches(const std::filesystem::path            &folder,
                 const coupling::RveDatabase            &database,
                 const std::vector<coupling::DpcFitRow> &fit = {});

  /// validation.csv: per path, the fitted law against the RVE it was
  /// fitted to, against the held-out packing, and the RVE's own
  /// packing-to-packing scatter.
  void
  write_validation(
    const std::filesystem::path                     &folder,
    const std::vector<coupling::DatabaseComparison> &comparisons);

  /// validation_rows.csv: the RVE's and the law's stress at every row.
  void
  write_validation_rows(const std::filesystem::path &folder,
                        const coupling::RveDatabase &rve,
                        const coupling::RveDatabase &law);

  /// validation.png: p and q of the RVE and of the fitted law at every
  /// row of validation_rows.csv.
  void
  plot_validation(const std::filesystem::path &folder);
} // namespace compax::cli
