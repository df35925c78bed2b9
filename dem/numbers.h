#pragma once

namespace compax::dem
{
  /// pi to double precision, for every file of dem/ (C++17 has no
  /// std::numbers; fem/ and coupling/ use dealii::numbers::PI).
  inline constexpr double pi = 3.14159265358979323846;
} // namespace compax::dem
