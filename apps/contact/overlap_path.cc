#include "apps/contact/overlap_path.h"

#include "apps/cli/parameters.h"

namespace compax::cli
{
  void
  declare_overlap_path(dealii::ParameterHandler &prm,
                       const std::string        &default_turning_points)
  {
    prm.enter_subsection("Overlap history");
    declare_quantity(
      prm,
      "Turning points",
      default_turning_points,
      dealii::Patterns::List(dealii::Patterns::Double(), 2),
      "m",
      "Comma-separated overlaps gamma at which the loading direction "
      "turns, first to last, at least two (e.g. 0, gmax, g1, g2: load, "
      "unload, reload). gamma > 0 is compression.");
    prm.declare_entry("Steps per segment",
                      "400",
                      dealii::Patterns::Integer(1, 1000000),
                      "Number of equal overlap steps between two turning "
                      "points, in [1, 1000000].");
    prm.leave_subsection();
  }

  std::vector<double>
  sample_piecewise_linear(const std::vector<double> &turning_points,
                          const unsigned int         steps)
  {
    std::vector<double> path{turning_points.front()};
    for (std::size_t s = 1; s < turning_points.size(); ++s)
      for (unsigned int i = 1; i <= steps; ++i)
        {
          const double t = static_cast<double>(i) / steps;
          path.push_back((1.0 - t) * turning_points[s - 1]
                         + t * turning_points[s]);
        }
    return path;
  }

  std::vector<double>
  get_overlap_path(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Overlap history");
    const auto points = get_real_list(prm, "Turning points");
    const auto steps  = prm.get_integer("Steps per segment");
    prm.leave_subsection();
    return sample_piecewise_linear(points, static_cast<unsigned int>(steps));
  }
} // namespace compax::cli
