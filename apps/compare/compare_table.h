#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace compax::cli
{
  /// A quantity sampled against relative density, e.g. punch pressure along
  /// a compaction path: x [-] and y (any unit), in the order sampled.
  struct DensitySeries
  {
    std::vector<double> x, y;
  };

  /**
   * y of @p s at @p x by linear interpolation between the two samples that
   * bracket x (the samples are sorted by x first; exact at a sample). Within
   * @p reach beyond the first or last sample the end segment is extended
   * (a sample at 0.750008 stands for 0.75); further out, or when s is
   * empty, NaN: no extrapolation.
   */
  double
  interpolate(const DensitySeries &s, double x, double reach = 0.0);

  /// One row of compare.csv.
  struct ComparisonRow
  {
    std::string comparison;
    double      relative_density;
    double      reference;
    /// NaN when the compared study has no value there (written empty).
    double value;

    /// (value - reference) / |reference|; NaN when value is missing.
    double
    relative_difference() const;
  };

  /**
   * Rows of one comparison: at every sample of @p reference whose value
   * is non-zero (a relative difference needs one), the reference and the
   * compared series interpolated at that density (missing outside its
   * range widened by @p reach, see interpolate()).
   */
  std::vector<ComparisonRow>
  compare_series(const std::string   &comparison,
                 const DensitySeries &reference,
                 const DensitySeries &compared,
                 double               reach = 0.0);

  /// The columns of compare.csv, in order.
  const std::vector<std::string> &
  comparison_columns();

  /// compare.csv: comparison,relative_density,reference,value,
  /// relative_difference (missing values are empty cells).
  void
  write_comparison_csv(const std::filesystem::path      &file,
                       const std::vector<ComparisonRow> &rows);

  /**
   * A CSV file written by a compax command, as its columns by name (text
   * cells as they are). Throws std::runtime_error naming the file when it
   * is missing or a column asked for is not there.
   */
  class CsvTable
  {
  public:
    explicit CsvTable(const std::filesystem::path &file);

    std::size_t
    rows() const
    {
      return n_rows;
    }

    bool
    has(const std::string &column) const;

    /// The cells of a column as text.
    const std::vector<std::string> &
    text(const std::string &column) const;

    /// The cells of a column as numbers (NaN for empty or text cells).
    std::vector<double>
    numbers(const std::string &column) const;

  private:
    std::filesystem::path                           file;
    std::map<std::string, std::vector<std::string>> cells;
    std::size_t                                     n_rows = 0;
  };
} // namespace compax::cli
