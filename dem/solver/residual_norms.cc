#include "dem/solver/residual_norms.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace compax::dem
{
  double
  max_particle_norm(const Eigen::VectorXd &F)
  {
    double m = 0.0;
    for (Eigen::Index i = 0; i + 2 < F.size(); i += 3)
      m = std::max(m, F[i] * F[i] + F[i + 1] * F[i + 1] + F[i + 2] * F[i + 2]);
    return std::sqrt(m);
  }

  double
  relative_residual(const Eigen::VectorXd &F, const ContactSums &sums)
  {
    const double fmax = max_particle_norm(F);
    if (sums.mean_force > 0.0)
      return fmax / sums.mean_force;
    return fmax == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  }

  RelaxationBalance
  relaxation_balance(const Eigen::VectorXd &F,
                     const ContactSums     &sums,
                     const double           target,
                     const double           force_floor)
  {
    const double      fmax = max_particle_norm(F);
    RelaxationBalance b;
    b.relative_residual = sums.mean_force > 0.0 ? fmax / sums.mean_force : 0.0;
    b.balanced_below    = std::max(target * sums.mean_force, force_floor);
    b.balanced          = fmax <= b.balanced_below;
    b.largest_force     = fmax;
    return b;
  }
} // namespace compax::dem
