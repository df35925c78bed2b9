#include "dem/rve/deposited_packing.h"

#include "dem/numbers.h"
#include "dem/packing/ballistic_deposition.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// Mean sphere volume of a size distribution, from 4096 draws of an
    /// independent stream (exact when monodisperse) [m^3].
    double
    mean_volume(const SizeDistribution &sizes, const std::uint64_t seed)
    {
      RandomSource random(seed ^ 0x9e3779b97f4a7c15ULL);
      double       sum = 0.0;
      const int    n   = 4096;
      for (int k = 0; k < n; ++k)
        sum += std::pow(sizes.sample(random), 3);
      return 4.0 / 3.0 * pi * sum / n;
    }

    /// The smallest period P >= period in z such that no sphere overlaps
    /// the image, shifted by P, of another sphere of the slab.
    double
    seam_free_period(const ParticleSystem &p,
                     const double          side,
                     const double          period)
    {
      double P = period;
      for (std::size_t a = 0; a < p.size(); ++a)
        for (std::size_t b = 0; b < p.size(); ++b)
          {
            Eigen::Vector3d d = p.positions[a] - p.positions[b];
            for (int k = 0; k < 2; ++k)
              d[k] -= side * std::round(d[k] / side);
            const double s  = p.radii[a] + p.radii[b];
            const double h2 = d[0] * d[0] + d[1] * d[1];
            // Sphere a near the top against the image of b above it.
            if (h2 < s * s)
              P = std::max(P, d[2] + std::sqrt(s * s - h2));
          }
      return P;
    }
  } // namespace

  PeriodicBed
  make_deposited_packing(const DepositedPackingSpec &spec)
  {
    if (spec.particle_count < 2)
      throw std::invalid_argument(
        "deposited packing: need at least 2 particles");
    if (!(spec.margin_diameters >= 0.0))
      throw std::invalid_argument(
        "deposited packing: the margin must be non-negative");
    const double v = mean_volume(spec.sizes, spec.seed);
    const double d = 2.0 * std::cbrt(3.0 * v / (4.0 * pi));
    // A cubic cell at a core density of about 0.58.
    const double side   = std::cbrt(spec.particle_count * v / 0.58);
    const double margin = spec.margin_diameters * d;

    DepositionParameters deposition;
    deposition.die_diameter = side;
    deposition.container    = DepositionContainer::periodic_square;
    deposition.sizes        = spec.sizes;
    deposition.seed         = spec.seed;
    double columns = spec.particle_count * (1.0 + (2.0 * margin + d) / side);
    for (int attempt = 0; attempt < 8; ++attempt, columns *= 1.3)
      {
        deposition.n_particles = static_cast<std::size_t>(1.15 * columns) + 8;
        const ParticleSystem deposit = ballistic_deposition(deposition);
        double               top     = 0.0;
        for (std::size_t i = 0; i < deposit.size(); ++i)
          top = std::max(top, deposit.positions[i][2]);
        // The core: centres above the margin, sorted by height.
        std::vector<std::size_t> core;
        for (std::size_t i = 0; i < deposit.size(); ++i)
          if (deposit.positions[i][2] >= margin)
            core.push_back(i);
        std::stable_sort(core.begin(),
                         core.end(),
                         [&](std::size_t a, std::size_t b) {
                           return deposit.positions[a][2]
                                  < deposit.positions[b][2];
                         });
        if (core.size() <= spec.particle_count)
          continue;
        const double z_next = deposit.positions[core[spec.particle_count]][2];
        if (z_next > top - margin)
          continue; // the slab would reach into the loose surface

        PeriodicBed bed;
        for (std::size_t k = 0; k < spec.particle_count; ++k)
          {
            Eigen::Vector3d x = deposit.positions[core[k]];
            x[0] += 0.5 * side;
            x[1] += 0.5 * side;
            x[2] -= margin;
            bed.particles.add(x, deposit.radii[core[k]], spec.material);
          }
        const double z_last
          = deposit.positions[core[spec.particle_count - 1]][2];
        const double period
          = seam_free_period(bed.particles,
                             side,
                             0.5 * (z_last + z_next) - margin);
        bed.cell = PeriodicCell::box(Eigen::Vector3d(side, side, period),
                                     {true, true, true});
        bed.reference_lattice = bed.cell.lattice();
        bed.deformation       = Eigen::Matrix3d::Identity();
        for (auto &x : bed.particles.positions)
          bed.cell.wrap(x);
        bed.contacts.set_skin(spec.skin * bed.particles.mean_radius());
        return bed;
      }
    throw std::runtime_error("deposited packing: the deposit did not grow a "
                             "core of the requested size");
  }
} // namespace compax::dem
