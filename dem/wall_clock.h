#pragma once

#include <chrono>

namespace compax::dem
{
  /// Wall time [s] since @p start on the steady clock: the one way every
  /// study, solver and command times its work for its reports.
  inline double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now()
                                         - start)
      .count();
  }
} // namespace compax::dem
