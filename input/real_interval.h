#pragma once

#include <deal.II/base/patterns.h>

#include <memory>
#include <string>

namespace compax::input
{
  /**
   * A real number in an interval whose ends may be open or closed, e.g.
   * "(0, inf)" for a modulus or "(-1, 0.5)" for a Poisson's ratio. deal.II's
   * Patterns::Double has closed ends only, and E = 0 or nu = 0.5 must be
   * rejected at parse time with the allowed range in the message.
   */
  class RealInterval : public dealii::Patterns::PatternBase
  {
  public:
    RealInterval(double lower, bool lower_open, double upper, bool upper_open);

    bool
    match(const std::string &text) const override;

    std::string
    description(OutputStyle style = Machine) const override;

    std::unique_ptr<dealii::Patterns::PatternBase>
    clone() const override;

    /// The interval in mathematical notation, e.g. "(0, inf)".
    std::string
    interval() const;

  private:
    double lower, upper;
    bool   lower_open, upper_open;
  };

  /// (0, inf)
  RealInterval
  positive();
  /// [0, inf)
  RealInterval
  non_negative();
  /// [lower, upper]
  RealInterval
  closed(double lower, double upper);
  /// (lower, upper)
  RealInterval
  open(double lower, double upper);
} // namespace compax::input
