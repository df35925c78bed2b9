#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ostream>

namespace compax::input
{
  /**
   * Prints the parameters as a valid .prm with their documentation (what
   * `--print-parameters` shows), every entry with its allowed values: an
   * entry whose documentation does not state them ("Allowed: ...") gets a
   * line "Allowed: ..." from its pattern (integer ranges, selections,
   * lists).
   */
  void
  print_documented_parameters(const dealii::ParameterHandler &prm,
                              std::ostream                   &out);

  /**
   * Every entry of @p prm as Markdown tables (entry, default, allowed
   * values, meaning with its unit), one per subsection, subsections under
   * headings of @p level '#' (nested ones one level deeper): the reference
   * that `compax docs` writes, from the same declarations as
   * print_documented_parameters().
   */
  void
  write_parameters_markdown(const dealii::ParameterHandler &prm,
                            int                             level,
                            std::ostream                   &out);
} // namespace compax::input
