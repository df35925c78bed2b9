#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace compax::cli
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

  /**
   * Declares an entry whose documentation names its unit, e.g.
   * declare_quantity(prm, "Young's modulus", "5e9", positive(), "Pa",
   * "Young's modulus E of the particle material.").
   */
  void
  declare_quantity(dealii::ParameterHandler            &prm,
                   const std::string                   &name,
                   const std::string                   &default_value,
                   const dealii::Patterns::PatternBase &pattern,
                   const std::string                   &unit,
                   const std::string                   &documentation);

  /// Folder of the parameter file parsed last (absolute), empty before
  /// any: relative file names inside a .prm are relative to it.
  std::filesystem::path
  parameter_file_directory();

  /// A file named in a .prm: absolute as given, relative to the .prm's
  /// folder otherwise (the current folder when no file was parsed).
  std::filesystem::path
  resolve_input_path(const std::string &path);

  /**
   * Parses a .prm file into prm. A missing file, an unknown entry, a
   * malformed or out-of-range value all become one InputError whose message
   * names the file, line, entry, value and allowed range.
   */
  void
  parse_parameter_file(dealii::ParameterHandler    &prm,
                       const std::filesystem::path &file);

  /// A comma-separated list of reals read from an entry declared with
  /// Patterns::List(Patterns::Double()).
  std::vector<double>
  get_real_list(dealii::ParameterHandler &prm, const std::string &name);

  /// A number as a .prm or message shows it ("5e+09", "0.25").
  std::string
  format_number(double value);

  /**
   * The canonical text of the entries that must match when a run resumes
   * from an archive (its fingerprint is stored with the archive): one line
   * "Subsection/Entry = value" per entry whose path is or lies below one of
   * @p include (every entry if it is empty) and neither is nor lies below
   * one of @p exclude, in declaration order. Numbers are written in their
   * shortest exact form (so 2e-4 and 2.0e-4 agree), each item of a
   * comma-separated list alike, and yes/no as true/false. For the entries
   * in @p files the value is the content of the file they name (resolved
   * as resolve_input_path() does; "missing" if it cannot be read).
   */
  std::string
  canonical_parameters(const dealii::ParameterHandler &prm,
                       const std::vector<std::string> &include,
                       const std::vector<std::string> &exclude = {},
                       const std::vector<std::string> &files   = {});

  /**
   * Throws an InputError naming the first entry with a real-number pattern
   * whose value (or an item of its list) under- or overflows a double
   * (e.g. 1e-320): deal.II's patterns accept such values, but reading them
   * fails. Called by parse_parameter_file().
   */
  void
  check_representable_numbers(const dealii::ParameterHandler &prm);

  /**
   * Prints the parameters as a valid .prm with their documentation (what
   * `--print-parameters` shows), every entry with its allowed values: an
   * entry whose documentation does not state them ("Allowed: ...") gets a
   * line "Allowed: ..." from its pattern (integer ranges, selections,
   * lists).
   */
  /**
   * Every entry of @p prm as Markdown tables (entry, default, allowed
   * values, meaning with its unit), one per subsection, subsections under
   * headings of @p level '#' (nested ones one level deeper): the reference
   * that `compax docs` writes, from the same declarations as
   * --print-parameters.
   */
  void
  write_parameters_markdown(const dealii::ParameterHandler &prm,
                            int                             level,
                            std::ostream                   &out);

  void
  print_documented_parameters(const dealii::ParameterHandler &prm,
                              std::ostream                   &out);

  /// Throws an InputError "entry 'name' = value: message" for checks that
  /// involve several entries.
  [[noreturn]] void
  reject_entry(const std::string &name,
               const std::string &value,
               const std::string &message);
} // namespace compax::cli
