#pragma once

#include "dem/packing/random_source.h"
#include "dem/rve/periodic_bed.h"
#include "dem/solver/contact_model.h"

#include <cstddef>
#include <cstdint>

namespace compax::dem
{
  /// A periodic packing to generate.
  struct PeriodicPackingSpec
  {
    std::size_t particle_count = 500;
    /// Radii (monodisperse or log-normal with cut-offs).
    SizeDistribution sizes;
    /// Solid fraction of the packing returned [-]; above random close
    /// packing (~0.64) the packing is already compressed and loaded.
    double relative_density = 0.55;
    /// Solid fraction at which the spheres are inserted at random [-]
    /// (random sequential addition jams near 0.38).
    double insertion_density = 0.25;
    /// Verlet skin as a fraction of the mean radius [-].
    double        skin = 0.3;
    std::uint64_t seed = 1;
    /// Material of every particle (an index of the ContactModel).
    unsigned int material = 0;
  };

  /**
   * A fully periodic cubic cell of virgin spheres at a given relative
   * density, by compression of a loose gas: the spheres are inserted at
   * random without overlap at insertion_density, then the cell is
   * compressed hydrostatically in small steps, each relaxed by FIRE with
   * frozen histories, so the returned packing carries no plastic history
   * (a_p = a_B = 0 everywhere). Reproducible: the same spec gives the same
   * cell.
   */
  PeriodicBed
  make_periodic_packing(const PeriodicPackingSpec &spec,
                        const ContactModel        &model);
} // namespace compax::dem
