#include "dem/solver/fire_relaxation.h"

#include "dem/solver/residual_norms.h"

#include "dem/solver/trust_region_newton.h"

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  FireResult
  FireRelaxation::relax(EquilibriumSystem &system,
                        const double       target,
                        const int          max_iterations,
                        const double       force_floor)
  {
    // FIRE (Bitzek et al. 2006) in units where a particle's own stiffness
    // over its mass is 1. (The FIRE 2.0 variant, with dt_max = 1 and the
    // half-step correction, converged more slowly to tight tolerances on
    // jammed beds.)
    const double dt_max = 0.5, alpha0 = 0.1, f_inc = 1.1, f_alpha = 0.99;
    const int    n_min = 5, mass_interval = 25;

    const std::size_t n = system.n_particles();
    v.setZero(3 * n);
    inverse_mass.resize(3 * n);
    const double cap = 0.1 * system.skin();

    start_watching();
    FireResult result;
    double     dt = 0.1, alpha = alpha0;
    int        n_positive = 0;
    assemble_inverse_diagonal(system, F, inverse_mass);
    ++result.assemblies;
    auto x = system.coordinates();
    for (int it = 0;; ++it)
      {
        record(result, relaxation_balance(F, sums, target, force_floor), it);
        if (result.converged || result.stalled || it >= max_iterations)
          break;
        // F is the gradient: the force is -F.
        const double power = -F.dot(v);
        if (power > 0.0)
          {
            const double vn = v.norm(), fn = F.norm();
            if (fn > 0.0)
              v = (1.0 - alpha) * v - (alpha * vn / fn) * F;
            if (++n_positive > n_min)
              {
                dt = std::min(f_inc * dt, dt_max);
                alpha *= f_alpha;
              }
          }
        else
          {
            n_positive = 0;
            dt *= 0.5;
            alpha = alpha0;
            v.setZero();
          }
        v.noalias() -= dt * F.cwiseProduct(inverse_mass);
        const double move = dt * max_particle_norm(v);
        if (move > cap)
          {
            v *= cap / move;
            dt = std::max(0.5 * dt, 1e-3);
          }
        x += dt * v;
        if (it % mass_interval == mass_interval - 1)
          {
            assemble_inverse_diagonal(system, F, inverse_mass);
            ++result.assemblies;
          }
        else
          sums = system.residual(F);
      }
    result.sums = sums;
    return result;
  }
} // namespace compax::dem
