#pragma once

#include "dem/packing/random_source.h"
#include "dem/rve/periodic_bed.h"
#include "dem/solver/contact_model.h"

#include <cstddef>
#include <cstdint>

namespace compax::dem
{
  /// How the starting packing of an RVE is made (make_rve_packing()).
  enum class PackingProtocol
  {
    /// Compression of a random gas with frozen histories
    /// (make_periodic_packing()).
    compressed_gas,
    /// A periodic cell cut from a ballistic deposit
    /// (make_deposited_packing()), compacted uniaxially on the RVE's
    /// loading path up to the requested density: the die's loose bed.
    deposited
  };

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
    /// Which packing make_rve_packing() makes (make_periodic_packing() is
    /// the compressed gas whatever this says); insertion_density is used
    /// by the compressed gas only.
    PackingProtocol protocol = PackingProtocol::compressed_gas;
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
