#include "dem/solver/fire_relaxation.h"

#include "dem/solver/trust_region_newton.h"

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  FireResult
  FireRelaxation::relax(Bed                &bed,
                        const ContactModel &model,
                        const double        target,
                        const int           max_iterations)
  {
    const std::size_t n = bed.particles.size();
    v.setZero(3 * n);
    mass.resize(3 * n);
    double       dt = 0.1, alpha = 0.1;
    const double dt_max = 0.5, alpha0 = 0.1;
    int          n_positive = 0;
    FireResult   result;

    auto update_mass = [&]() {
      const ContactSums s    = assembler.assemble(bed, model, F, K);
      double            mean = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        {
          const double *b = K.block(K.diagonal_slot(i));
          mean
            += std::max(b[0], 0.0) + std::max(b[4], 0.0) + std::max(b[8], 0.0);
        }
      mean = mean / (3.0 * std::max<std::size_t>(n, 1));
      if (mean <= 0.0)
        mean = 1.0;
      for (std::size_t i = 0; i < n; ++i)
        {
          const double *b = K.block(K.diagonal_slot(i));
          const double  k = std::max({b[0], b[4], b[8], 0.05 * mean});
          mass.segment<3>(3 * i).setConstant(k);
        }
      return s;
    };

    ContactSums sums = update_mass();
    for (int it = 0; it < max_iterations; ++it)
      {
        result.iterations        = it + 1;
        const double fmax        = max_particle_norm(F);
        result.relative_residual = sums.mean_force > 0.0
                                     ? fmax / sums.mean_force
                                     : (fmax == 0 ? 0 : 1e300);
        if (result.relative_residual <= target)
          break;
        // Force f = -F.
        const double power = -F.dot(v);
        if (power > 0.0)
          {
            const double vn = v.norm(), fn = F.norm();
            if (fn > 0.0)
              v = (1.0 - alpha) * v - alpha * vn / fn * F;
            if (++n_positive > 5)
              {
                dt = std::min(1.1 * dt, dt_max);
                alpha *= 0.99;
              }
          }
        else
          {
            n_positive = 0;
            dt *= 0.5;
            alpha = alpha0;
            v.setZero();
          }
        v -= dt * F.cwiseQuotient(mass);
        // No particle moves more than a tenth of the Verlet skin per
        // iteration, so that none can pass through a wall or a neighbour.
        const double move = dt * max_particle_norm(v);
        const double cap  = 0.1 * bed.contacts.skin();
        if (move > cap)
          {
            v *= cap / move;
            dt = std::max(0.5 * dt, 1e-3);
          }
        bed.particles.coordinates() += dt * v;
        if (it % 25 == 24)
          sums = update_mass();
        else
          sums = assembler.residual(bed, model, F);
      }
    return result;
  }
} // namespace compax::dem
