#include "dem/solver/load_stepper.h"

#include "dem/solver/punch_gap_map.h"
#include "dem/wall_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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
      , least_squares(equilibrium)
      , stepping(stepping)
  {
  }

  namespace
  {
    void
    accumulate(LoadStepResult &total, const EquilibriumResult &r)
    {
      total.work += r.work;
      total.last = r;
    }

  } // namespace

  bool
  LoadStepper::below_jamming(const Bed &bed, const ContactSums &sums) const
  {
    const double F = stepping.jamming_pressure * bed.walls.punch_area();
    return sums.wall_force[int(Wall::lower_punch)] < F
           && sums.wall_force[int(Wall::upper_punch)] < F;
  }

  bool
  LoadStepper::unjammed(Bed &bed)
  {
    if (loose < 0)
      {
        ContactAssembler assembler;
        Eigen::VectorXd  F;
        loose = below_jamming(bed, assembler.residual(bed, model, F)) ? 1 : 0;
      }
    return loose == 1;
  }

  FireResult
  LoadStepper::relax(Bed &bed, LoadStepResult &total)
  {
    if (stepping.unjammed_equilibrium == UnjammedEquilibrium::least_squares)
      {
        // Algorithm 1 as printed: converged where the step vanishes.
        const EquilibriumResult r = least_squares.solve(bed, model);
        accumulate(total, r);
        return as_relaxation(r);
      }
    // A balanced relaxation stops where Newton would: at the relative force
    // tolerance or below the absolute force floor.
    const EquilibriumOptions &eq = newton.options();
    const auto                t0 = std::chrono::steady_clock::now();
    Relaxation &minimiser = relaxes_by_lbfgs(stepping.unjammed_equilibrium)
                              ? static_cast<Relaxation &>(lbfgs)
                              : static_cast<Relaxation &>(fire);
    const bool  balanced  = relaxes_to_balance(stepping.unjammed_equilibrium);
    minimiser.give_up_when_stalled(balanced ? stepping.balanced_stall_window
                                            : 0);
    const FireResult f = balanced
                           ? minimiser.relax(bed,
                                             model,
                                             eq.force_tolerance,
                                             stepping.balanced_iterations,
                                             eq.force_floor)
                           : minimiser.relax(bed,
                                             model,
                                             stepping.unjammed_tolerance,
                                             stepping.unjammed_iterations,
                                             stepping.force_resolution);
    total.work.fire_seconds += seconds_since(t0);
    total.work.fire_iterations += f.iterations;
    total.work.assemblies += f.assemblies;
    return f;
  }

  EquilibriumResult
  LoadStepper::relaxed_result(const FireResult &f, LoadStepResult &total)
  {
    total.last                   = EquilibriumResult{};
    total.last.converged         = true;
    total.last.relative_residual = f.relative_residual;
    total.last.sums              = f.sums;
    return total.last;
  }

  LoadStepper::UnjammedStep
  LoadStepper::relax_unjammed(Bed &bed, LoadStepResult &total)
  {
    if (!(stepping.jamming_pressure > 0.0) || loose != 1)
      return UnjammedStep::newton;
    const FireResult f = relax(bed, total);
    if (!below_jamming(bed, f.sums))
      return UnjammedStep::newton; // the bed jams in this sub-step
    if (!f.converged)
      return UnjammedStep::failed;
    relaxed_result(f, total);
    return UnjammedStep::relaxed;
  }

  EquilibriumResult
  LoadStepper::solve_substep(Bed &bed, LoadStepResult &total)
  {
    const UnjammedStep u           = relax_unjammed(bed, total);
    const bool         then_newton = stepping.unjammed_equilibrium
                             == UnjammedEquilibrium::relaxation_then_newton;
    total.relaxed = u == UnjammedStep::relaxed && !then_newton;
    if (total.relaxed)
      return total.last;
    // A relaxation that did not converge cuts the sub-step back, unless
    // Newton balances the relaxed states anyway: then it continues from
    // where the relaxation got to.
    if (u == UnjammedStep::failed && !then_newton)
      return EquilibriumResult{}; // not converged: the sub-step is cut
    const EquilibriumResult r = newton.solve(bed, model);
    accumulate(total, r);
    return r;
  }

  void
  LoadStepper::commit(Bed &bed, const ContactSums &sums, LoadStepResult &total)
  {
    const BondChanges b
      = bed.contacts.update_histories(bed.particles,
                                      bed.walls,
                                      stepping.resolved_history
                                        ? stepping.force_resolution
                                        : 0.0);
    total.bonds.formed += b.formed;
    total.bonds.broken += b.broken;
    // A bed that has jammed once stays a solid: its unloading and ejection
    // are static equilibria solved by Newton, however small the punch load
    // (relax_coming_apart() only takes over where Newton fails).
    if (loose != 0)
      loose = below_jamming(bed, sums) ? 1 : 0;
  }

  EquilibriumResult
  LoadStepper::relax_coming_apart(Bed            &bed,
                                  const DieWalls &next,
                                  LoadStepResult &total)
  {
    if (!(stepping.jamming_pressure > 0.0) || loose != 0
        || !relaxes_to_balance(stepping.unjammed_equilibrium)
        || !(next.height() > saved.walls.height()))
      return EquilibriumResult{};
    bed = saved;
    predict(bed, next);
    bed.walls          = next;
    const FireResult f = relax(bed, total);
    if (!f.converged)
      return EquilibriumResult{};
    total.relaxed = true;
    return relaxed_result(f, total);
  }

  void
  LoadStepper::predict(Bed &bed, const DieWalls &next)
  {
    const DieWalls &w        = bed.walls;
    const double    delta[3] = {next.lower_punch - w.lower_punch,
                                next.upper_punch - w.upper_punch,
                                next.diameter - w.diameter};
    double          dot = 0.0, nn = 0.0, oo = 0.0;
    for (int k = 0; k < 3; ++k)
      {
        dot += delta[k] * last_delta[k];
        nn += delta[k] * delta[k];
        oo += last_delta[k] * last_delta[k];
      }
    const bool secant = stepping.secant_predictor
                        && (stepping.secant_predictor_unjammed || loose != 1);
    const bool parallel
      = secant && have_increment && nn > 0.0 && oo > 0.0
        && dot > 0.999 * std::sqrt(nn * oo) && next.die_present == w.die_present
        && last_die_present == w.die_present
        && last_increment.size()
             == static_cast<Eigen::Index>(3 * bed.particles.size());
    if (parallel)
      bed.particles.coordinates() += (dot / oo) * last_increment;
    else
      map_heights(bed.particles, w, next, GapParticles::between_punches);
  }

  LoadStepResult
  LoadStepper::equilibrate(Bed &bed)
  {
    LoadStepResult total;
    if (stepping.jamming_pressure > 0.0)
      unjammed(bed);
    const EquilibriumResult r = solve_substep(bed, total);
    total.substeps            = 1;
    total.converged           = r.converged;
    if (r.converged)
      commit(bed, r.sums, total);
    return total;
  }

  LoadStepResult
  LoadStepper::advance(Bed &bed, const DieWalls &target)
  {
    LoadStepResult total;
    const DieWalls start = bed.walls;
    if (stepping.jamming_pressure > 0.0)
      unjammed(bed); // known before the predictor moves the particles
    double done = 0.0;
    fraction    = std::min(std::max(fraction, stepping.min_fraction), 1.0);
    while (done < 1.0)
      {
        const double t      = std::min(1.0, done + fraction);
        saved               = bed;
        const DieWalls next = t >= 1.0 ? target : interpolate(start, target, t);
        predict(bed, next);
        bed.walls        = next;
        const bool opens = next.height() > saved.walls.height();
        coming_apart     = coming_apart && opens;
        EquilibriumResult r;
        if (!coming_apart)
          r = solve_substep(bed, total);
        if (!r.converged
            && (coming_apart || stepping.relax_opening_at_first_failure
                || 0.5 * fraction < stepping.min_fraction))
          {
            r            = relax_coming_apart(bed, next, total);
            coming_apart = r.converged;
          }
        if (r.converged)
          {
            last_increment
              = bed.particles.coordinates() - saved.particles.coordinates();
            last_delta[0]    = next.lower_punch - saved.walls.lower_punch;
            last_delta[1]    = next.upper_punch - saved.walls.upper_punch;
            last_delta[2]    = next.diameter - saved.walls.diameter;
            last_die_present = next.die_present;
            have_increment   = true;
            commit(bed, r.sums, total);
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
