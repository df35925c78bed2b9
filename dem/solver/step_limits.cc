#include "dem/solver/step_limits.h"

namespace compax::dem
{
  bool
  limit_step_to_gaps(const EquilibriumSystem &system,
                     Eigen::VectorXd         &s,
                     Eigen::VectorXd         &factor)
  {
    const std::size_t n = system.n_particles();
    factor.setOnes(n);
    bool         clipped = system.limit_closing(s, factor);
    const double cap     = 0.25 * system.skin();
    for (std::size_t i = 0; i < n; ++i)
      {
        const double len = s.segment<3>(3 * i).norm();
        if (len * factor[i] > cap)
          {
            factor[i] = cap / len;
            clipped   = true;
          }
      }
    if (clipped)
      for (std::size_t i = 0; i < n; ++i)
        s.segment<3>(3 * i) *= factor[i];
    return clipped;
  }
} // namespace compax::dem
