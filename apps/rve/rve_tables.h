#pragma once

#include "dem/rve/rve_path_study.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace compax::cli
{
  /// Columns of rve.csv and moduli.csv (one row = one vector of numbers in
  /// this order; the stage is 0 loading / 1 unloading, NaN an empty cell).
  /// Checkpoints store the rows in this layout.
  const std::vector<std::string> &
  rve_columns();
  const std::vector<std::string> &
  moduli_columns();

  /// Columns of timing.csv: per row of rve.csv computed by this run, the
  /// seconds of its step and of its tangents (kept out of rve.csv and
  /// moduli.csv, so that two runs of one study give the same files).
  const std::vector<std::string> &
  timing_columns();

  /// Index of a column in rve_columns() / moduli_columns().
  std::size_t
  rve_column(const std::string &name);
  std::size_t
  moduli_column(const std::string &name);

  /// A state of the path as a row of rve.csv.
  std::vector<double>
  rve_row(const dem::RvePathStep &step);

  /// Tangents and moduli as a row of moduli.csv.
  std::vector<double>
  moduli_row(const dem::RvePathModuli &moduli);

  /// The rows of timing.csv of a run.
  std::vector<std::vector<double>>
  timing_rows(const dem::RvePathResult &result);

  /// Writes rows of numbers; "stage" as text, NaN as an empty cell.
  void
  write_table(const std::filesystem::path            &file,
              const std::vector<std::string>         &columns,
              const std::vector<std::vector<double>> &rows);
} // namespace compax::cli
