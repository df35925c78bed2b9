#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace compax::cli
{
  /**
   * Declares subsection "Overlap history": the turning points of a
   * piecewise-linear history of the overlap gamma [m] and the number of
   * steps per segment.
   */
  void
  declare_overlap_path(dealii::ParameterHandler &prm,
                       const std::string        &default_turning_points);

  /// The sampled overlaps, turning points included, first to last.
  std::vector<double>
  get_overlap_path(dealii::ParameterHandler &prm);

  /// Samples a piecewise-linear path with `steps` steps per segment.
  std::vector<double>
  sample_piecewise_linear(const std::vector<double> &turning_points,
                          unsigned int               steps);
} // namespace compax::cli
