#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace compax::coupling
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

  /// One compared sample: a row of compax compare's compare.csv.
  struct ComparisonRow
  {
    std::string comparison;
    double      relative_density;
    double      reference;
    /// NaN when the compared study has no value there.
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

  /// How close the rows of one comparison are: what a report states about
  /// it.
  struct ComparisonSummary
  {
    /// Rows with a relative difference, and rows without (missing value).
    std::size_t compared = 0, missing = 0;
    /// Sum and largest of the absolute relative differences [-].
    double sum_abs = 0.0, largest_abs = 0.0;
  };

  /// The summary of the rows named @p comparison among @p rows.
  ComparisonSummary
  summarize(const std::vector<ComparisonRow> &rows,
            const std::string                &comparison);
} // namespace compax::coupling
