#include "dem/nonlocal/square_die_compaction.h"

#include "dem/solver/fire_relaxation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace compax::dem
{
  BedCompactionResult
  compact_square_die_bed(ParticleSystem                      particles,
                         const std::vector<ElasticMaterial> &materials,
                         SquareDie                           die,
                         const bool                          nonlocal,
                         const BedCompactionOptions         &options,
                         std::ostream                       *progress)
  {
    NonlocalBedOptions bed_options;
    bed_options.nonlocal = nonlocal;
    NonlocalBedSystem   system(particles, materials, die, bed_options);
    FireRelaxation      fire;
    TrustRegionNewton   newton(options.newton);
    NewtonKrylov        krylov(options.krylov);
    TrustRegionNewton   exact(options.nonlocal_newton, options.krylov);
    Eigen::VectorXd     F;
    BedCompactionResult result;

    const double solid  = particles.solid_volume();
    const double area   = die.width * die.width;
    const double R_mean = particles.mean_radius();
    const double floor = options.force_floor_fraction * options.jamming_pressure
                         * 3.14159265358979323846 * R_mean * R_mean;
    bool jammed = false;

    const auto record = [&](BedCompactionPoint &pt) {
      pt.relative_density = solid / die.enclosed_volume();
      pt.height           = die.height();
      pt.wall_force       = system.wall_forces();
      pt.lateral_force    = 0.25
                         * (pt.wall_force[SquareDie::x_lower]
                            + pt.wall_force[SquareDie::x_upper]
                            + pt.wall_force[SquareDie::y_lower]
                            + pt.wall_force[SquareDie::y_upper]);
      pt.coordination
        = 2.0 * static_cast<double>(system.n_loaded()) / particles.size();
      pt.nonlocal_ratio = system.max_nonlocal_ratio();
    };

    std::vector<Eigen::Vector3d> saved, previous, affine_positions;
    double                       previous_dH = 0.0;
    for (int step = 0;; ++step)
      {
        const double start = solid / die.enclosed_volume();
        const double target
          = std::min(options.final_density,
                     start + (step == 0 ? 0.0 : options.density_step));
        if (step > 0 && start >= options.final_density * (1.0 - 1e-12))
          {
            result.complete = true;
            break;
          }
        saved                 = particles.positions;
        const SquareDie old   = die;
        const double    H     = solid / (target * area);
        const double    z0    = die.lower_punch_height;
        const double    ratio = H / die.height();
        for (auto &x : particles.positions)
          x[2] = z0 + (x[2] - z0) * ratio;
        die.upper_punch_height = z0 + H;
        if (jammed && options.secant_predictor && !previous.empty()
            && previous_dH != 0.0)
          {
            // Secant predictor: the last converged increment, scaled to
            // this punch move, if it leaves a smaller residual than the
            // affine one.
            const double scale = (H - old.height()) / previous_dH;
            system.residual(F);
            const double affine
              = F.allFinite() ? F.norm() : std::numeric_limits<double>::max();
            affine_positions = particles.positions;
            for (std::size_t i = 0; i < particles.size(); ++i)
              particles.positions[i]
                = saved[i] + scale * (saved[i] - previous[i]);
            system.residual(F);
            if (!(F.allFinite() && F.norm() < affine))
              particles.positions = affine_positions;
          }

        BedCompactionPoint pt;
        const std::size_t  sweeps0 = system.total_sweeps();
        bool               ok      = true;
        if (!jammed)
          {
            if (nonlocal && options.hertz_consolidation)
              system.set_nonlocal(false);
            const FireResult fr = fire.relax(system,
                                             options.fire_tolerance,
                                             options.fire_iterations,
                                             floor);
            pt.fire_iterations += fr.iterations;
            ok = fr.converged;
            system.residual(F);
            if (system.wall_forces()[SquareDie::upper_punch]
                >= options.jamming_pressure * area)
              jammed = true;
          }
        if (jammed)
          {
            if (nonlocal && !system.options().nonlocal)
              system.set_nonlocal(true);
            pt.jammed = true;
            bool done = false;
            if (options.solver == BedSolver::nonlocal_trust_region && nonlocal)
              {
                const EquilibriumResult tr = exact.solve(system);
                pt.newton_iterations
                  += tr.work.iterations + tr.krylov_iterations;
                pt.rejected_steps += tr.rejected_steps;
                pt.fire_iterations += tr.work.fire_iterations;
                done = tr.converged;
              }
            if (options.solver == BedSolver::newton_krylov && nonlocal)
              {
                const NewtonKrylovResult nk = krylov.solve(system);
                pt.newton_iterations += nk.iterations;
                pt.rejected_steps += nk.backtracks;
                done = nk.converged;
              }
            if (!done)
              {
                const EquilibriumResult er = newton.solve(system);
                pt.newton_iterations += er.work.iterations;
                pt.rejected_steps += er.rejected_steps;
                pt.fire_iterations += er.work.fire_iterations;
                done = er.converged;
              }
            ok = done;
          }
        const ContactSums sums = system.residual(F);
        pt.relative_residual
          = F.allFinite() && sums.mean_force > 0.0
              ? max_particle_norm(F) / sums.mean_force
              : (F.allFinite() ? 0.0 : std::numeric_limits<double>::infinity());
        pt.converged = ok;
        pt.sweeps    = system.total_sweeps() - sweeps0;
        if (!ok)
          {
            result.failure_density = target;
            result.stop_reason
              = !F.allFinite() || !system.fixed_point().converged
                  ? "Algorithm 1 diverges (limit point of the nonlocal "
                    "formulation)"
                  : "the equilibrium solver did not converge";
            particles.positions = saved;
            die                 = old;
            system.invalidate();
            break;
          }
        record(pt);
        result.points.push_back(pt);
        if (pt.jammed)
          {
            previous    = saved;
            previous_dH = die.height() - old.height();
          }
        if (progress)
          *progress << "  rho " << pt.relative_density << "  upper punch "
                    << pt.wall_force[SquareDie::upper_punch] << " N  lateral "
                    << pt.lateral_force << " N  "
                    << (pt.jammed ? "newton " : "fire ")
                    << (pt.jammed ? pt.newton_iterations : pt.fire_iterations)
                    << "  sweeps " << pt.sweeps << '\n';
      }
    result.particles = particles;
    return result;
  }
} // namespace compax::dem
