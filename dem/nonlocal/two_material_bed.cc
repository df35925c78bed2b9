#include "dem/nonlocal/two_material_bed.h"

#include "dem/nonlocal/nonlocal_bed_system.h"
#include "dem/nonlocal/square_die_deposition.h"
#include "dem/numbers.h"
#include "dem/wall_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace compax::dem
{
  double
  mean_sphere_volume(const SizeDistribution &d)
  {
    return 4.0 / 3.0 * pi * std::pow(d.median_radius, 3)
           * std::exp(4.5 * d.log_sigma * d.log_sigma);
  }

  std::vector<std::size_t>
  material_counts(const TwoMaterialBed &bed, const std::size_t n)
  {
    const double f  = bed.volume_fraction_2;
    const double v1 = mean_sphere_volume(bed.sizes[0]);
    const double v2 = mean_sphere_volume(bed.sizes[1]);
    const auto   n2 = static_cast<std::size_t>(
      std::lround(n * f * v1 / ((1.0 - f) * v2 + f * v1)));
    return {n - std::min(n, n2), std::min(n, n2)};
  }

  ParticleSystem
  deposit_bed(const TwoMaterialBed &bed,
              const double          width,
              const std::size_t     n)
  {
    SquareDepositionParameters d;
    d.width  = width;
    d.sizes  = {bed.sizes[0], bed.sizes[1]};
    d.counts = material_counts(bed, n);
    d.seed   = bed.seed;
    return square_die_deposition(d);
  }

  double
  bed_top(const ParticleSystem &p)
  {
    double top = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      top = std::max(top, p.positions[i][2] + p.radii[i]);
    return top;
  }

  SquareDie
  starting_die(const TwoMaterialBed &bed, const ParticleSystem &deposit)
  {
    SquareDie die;
    die.width = bed.width;
    const double H0
      = deposit.solid_volume() / (bed.initial_density * bed.width * bed.width);
    die.upper_punch_height = std::max(H0, bed_top(deposit));
    return die;
  }

  std::vector<FormulationDiscrepancy>
  formulation_discrepancies(const BedCompactionResult &hertz,
                            const BedCompactionResult &nonlocal)
  {
    std::vector<FormulationDiscrepancy> rows;
    for (const auto &a : hertz.points)
      for (const auto &b : nonlocal.points)
        if (std::abs(a.relative_density - b.relative_density)
            <= 1e-9 * a.relative_density)
          {
            FormulationDiscrepancy r;
            r.relative_density = a.relative_density;
            r.hertz_load       = a.wall_force[SquareDie::upper_punch];
            r.nonlocal_load    = b.wall_force[SquareDie::upper_punch];
            r.hertz_lateral    = a.lateral_force;
            r.nonlocal_lateral = b.lateral_force;
            const bool jammed  = a.jammed && b.jammed;
            if (jammed && r.hertz_load > 0.0)
              r.load_discrepancy
                = (r.nonlocal_load - r.hertz_load) / r.hertz_load;
            if (jammed && r.hertz_lateral > 0.0)
              r.lateral_discrepancy
                = (r.nonlocal_lateral - r.hertz_lateral) / r.hertz_lateral;
            rows.push_back(r);
          }
    return rows;
  }

  std::vector<ResidualTiming>
  time_bed_residuals(const TwoMaterialBed &bed,
                     const std::size_t     n_particles,
                     const int             repetitions)
  {
    const std::vector<ElasticMaterial> materials{bed.elastic[0],
                                                 bed.elastic[1]};
    // A die wide enough that the bed is about as high as it is wide.
    const double volume
      = n_particles
        * (mean_sphere_volume(bed.sizes[0]) + mean_sphere_volume(bed.sizes[1]))
        / 2.0;
    const double width
      = std::max(bed.width, std::cbrt(volume / bed.initial_density));
    ParticleSystem p = deposit_bed(bed, width, n_particles);
    SquareDie      die;
    die.width              = width;
    die.upper_punch_height = bed_top(p);
    // Affine compression by 2 % of the height loads the contacts of the
    // deposit.
    for (auto &x : p.positions)
      x[2] *= 0.98;
    die.upper_punch_height *= 0.98;

    std::vector<ResidualTiming> timings;
    for (const bool nonlocal : {false, true})
      {
        NonlocalBedOptions o;
        o.nonlocal = nonlocal;
        NonlocalBedSystem system(p, materials, die, o);
        Eigen::VectorXd   F;
        system.residual(F); // builds the list; cold start of Algorithm 1
        const unsigned cold = system.fixed_point().iterations;
        // Warm starts, as between Newton iterates: tiny moves.
        auto                  x       = system.coordinates();
        const Eigen::VectorXd x0      = x;
        const std::size_t     sweeps0 = system.total_sweeps();
        const auto            t0      = std::chrono::steady_clock::now();
        for (int r = 0; r < repetitions; ++r)
          {
            x = x0 * (1.0 + 1e-9 * (r % 2));
            system.residual(F);
          }
        const double t = seconds_since(t0) / repetitions;
        x              = x0;
        timings.push_back(
          {nonlocal,
           p.size(),
           system.n_candidates(),
           system.n_loaded(),
           system.n_incidences(),
           cold,
           double(system.total_sweeps() - sweeps0) / repetitions,
           t});
      }
    return timings;
  }
} // namespace compax::dem
