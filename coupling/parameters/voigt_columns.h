#pragma once

#include <string>
#include <vector>

namespace compax::coupling
{
  /// The CSV columns of a symmetric tensor in Voigt order, e.g. eps_xx,
  /// eps_yy, eps_zz, eps_yz, eps_xz, eps_xy for @p tensor = "eps": one
  /// spelling for every table that writes strains or stresses.
  std::vector<std::string>
  voigt_columns(const std::string &tensor);
} // namespace compax::coupling
