#include "dem/rve/periodic_packing.h"

#include "dem/numbers.h"
#include "dem/rve/periodic_bed_system.h"
#include "dem/solver/fire_relaxation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace compax::dem
{
  namespace
  {
    /// Random sequential addition in a fully periodic cube of edge L; the
    /// largest spheres first.
    std::vector<Eigen::Vector3d>
    insert_without_overlap(const std::vector<double> &radii,
                           const PeriodicCell        &cell,
                           const double               L,
                           RandomSource              &random)
    {
      std::vector<Eigen::Vector3d> x;
      x.reserve(radii.size());
      for (std::size_t k = 0; k < radii.size(); ++k)
        {
          bool placed = false;
          for (int attempt = 0; attempt < 10000 && !placed; ++attempt)
            {
              const Eigen::Vector3d trial(random.uniform(0.0, L),
                                          random.uniform(0.0, L),
                                          random.uniform(0.0, L));
              placed = true;
              for (std::size_t q = 0; q < x.size() && placed; ++q)
                placed = cell.minimum_image(trial - x[q]).norm()
                         >= radii[k] + radii[q];
              if (placed)
                x.push_back(trial);
            }
          if (!placed)
            throw std::runtime_error(
              "periodic packing: no room to insert sphere "
              + std::to_string(k + 1) + " of " + std::to_string(radii.size())
              + "; lower the insertion density");
        }
      return x;
    }
  } // namespace

  PeriodicBed
  make_periodic_packing(const PeriodicPackingSpec &spec,
                        const ContactModel        &model)
  {
    if (spec.particle_count < 2)
      throw std::invalid_argument(
        "periodic packing: need at least 2 particles");
    if (!(spec.insertion_density > 0.0 && spec.insertion_density < 0.38))
      throw std::invalid_argument(
        "periodic packing: insertion density must lie in (0, 0.38)");
    RandomSource        random(spec.seed);
    std::vector<double> radii(spec.particle_count);
    double              solid = 0.0;
    for (double &r : radii)
      {
        r = spec.sizes.sample(random);
        solid += 4.0 / 3.0 * pi * r * r * r;
      }
    std::sort(radii.begin(), radii.end(), std::greater<>());
    const double L = std::cbrt(solid / spec.insertion_density);
    PeriodicBed  bed;
    bed.cell
      = PeriodicCell::box(Eigen::Vector3d::Constant(L), {true, true, true});
    bed.reference_lattice = bed.cell.lattice();
    bed.deformation       = Eigen::Matrix3d::Identity();
    const auto x          = insert_without_overlap(radii, bed.cell, L, random);
    for (std::size_t k = 0; k < radii.size(); ++k)
      bed.particles.add(x[k], radii[k], spec.material);
    bed.contacts.set_skin(spec.skin * bed.particles.mean_radius());

    // Hydrostatic compression of the gas, 1 % of volume per step, each
    // step relaxed by FIRE with frozen (virgin) histories to 1 % of the
    // mean contact force (Consolidation's tolerance).
    PeriodicAssembler assembler;
    FireRelaxation    fire;
    // Forces below that of an overlap of 1e-5 R count as touching.
    const double R = bed.particles.mean_radius();
    const double floor
      = law_response(model.pair_law(spec.material, R, spec.material, R),
                     1e-5 * R,
                     ContactHistory{})
          .force;
    double rho = bed.relative_density();
    while (rho < spec.relative_density * (1.0 - 1e-12))
      {
        const double next  = std::min(spec.relative_density, rho * 1.01);
        const double scale = std::cbrt(rho / next);
        map_affinely(bed, scale * bed.deformation);
        PeriodicBedSystem system(bed, model, assembler);
        fire.relax(system, 1e-2, 20000, floor);
        rho = bed.relative_density();
      }
    // The compressed packing is the new reference (F = I).
    bed.reference_lattice = bed.cell.lattice();
    bed.deformation       = Eigen::Matrix3d::Identity();
    return bed;
  }
} // namespace compax::dem
