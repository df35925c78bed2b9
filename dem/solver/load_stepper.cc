#include "dem/solver/load_stepper.h"

#include <algorithm>
#include <stdexcept>

namespace compax::dem
{
  DieWalls
  interpolate(const DieWalls &a, const DieWalls &b, const double t)
  {
    DieWalls w    = b;
    w.diameter    = a.diameter + t * (b.diameter - a.diameter);
    w.lower_punch = a.lower_punch + t * (b.lower_punch - a.lower_punch);
    w.upper_punch = a.upper_punch + t * (b.upper_punch - a.upper_punch);
    return w;
  }

  LoadStepper::LoadStepper(const ContactModel       &model,
                           const EquilibriumOptions  equilibrium,
                           const LoadSteppingOptions stepping)
      : model(model)
      , newton(equilibrium)
      , stepping(stepping)
  {
  }

  namespace
  {
    void
    accumulate(LoadStepResult &total, const EquilibriumResult &r)
    {
      total.iterations += r.iterations;
      total.cg_iterations += r.cg_iterations;
      total.assembly_seconds += r.assembly_seconds;
      total.linear_seconds += r.linear_seconds;
      total.assemblies += r.assemblies;
      total.fire_iterations += r.fire_iterations;
      total.fire_seconds += r.fire_seconds;
      total.last = r;
    }

    /// Affine map of the heights between the punches of `from` onto `to`.
    void
    predict(ParticleSystem &p, const DieWalls &from, const DieWalls &to)
    {
      const double h0 = from.height(), h1 = to.height();
      if (h0 <= 0.0 || h1 == h0)
        return;
      for (auto &x : p.positions)
        {
          const double t = (x[2] - from.lower_punch) / h0;
          if (t >= 0.0 && t <= 1.0)
            x[2] = to.lower_punch + t * h1;
        }
    }
  } // namespace

  LoadStepResult
  LoadStepper::equilibrate(Bed &bed)
  {
    LoadStepResult          total;
    const EquilibriumResult r = newton.solve(bed, model);
    accumulate(total, r);
    total.substeps  = 1;
    total.converged = r.converged;
    if (r.converged)
      total.bonds = bed.contacts.update_histories(bed.particles, bed.walls);
    return total;
  }

  LoadStepResult
  LoadStepper::advance(Bed &bed, const DieWalls &target)
  {
    LoadStepResult total;
    const DieWalls start = bed.walls;
    double         done  = 0.0;
    fraction = std::min(std::max(fraction, stepping.min_fraction), 1.0);
    while (done < 1.0)
      {
        const double t      = std::min(1.0, done + fraction);
        saved               = bed;
        const DieWalls next = t >= 1.0 ? target : interpolate(start, target, t);
        predict(bed.particles, bed.walls, next);
        bed.walls                 = next;
        const EquilibriumResult r = newton.solve(bed, model);
        accumulate(total, r);
        if (r.converged)
          {
            const BondChanges b
              = bed.contacts.update_histories(bed.particles, bed.walls);
            total.bonds.formed += b.formed;
            total.bonds.broken += b.broken;
            ++total.substeps;
            done     = t;
            fraction = std::min(1.0, fraction * stepping.growth);
          }
        else
          {
            bed = saved;
            ++total.cutbacks;
            fraction *= 0.5;
            if (fraction < stepping.min_fraction)
              {
                total.converged = false;
                fraction        = stepping.min_fraction;
                return total;
              }
          }
      }
    total.converged = true;
    return total;
  }
} // namespace compax::dem
