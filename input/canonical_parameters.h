#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace compax::input
{
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
} // namespace compax::input
