#pragma once

#include "dem/nonlocal/square_die.h"
#include "dem/nonlocal/square_die_compaction.h"
#include "dem/packing/random_source.h"
#include "dem/particles/particle_system.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

/**
 * @file
 * The disordered two-material bed of Gonzalez & Cuitino 2012, Sec. 4.2:
 * deposited ballistically into a square die and compacted once with Hertz
 * contacts and once with the nonlocal formulation; what the two
 * formulations predict at the same densities, and what one residual of
 * each costs on a large bed.
 */

namespace compax::dem
{
  /// What to deposit: two elastic materials with log-normal radii.
  struct TwoMaterialBed
  {
    /// Side L of the square die cross-section [m].
    double width = 1e-3;
    /// Particles in the bed.
    std::size_t n_particles = 125;
    /// Solid volume fraction of material 2 [-]; the counts follow from
    /// the mean volumes.
    double                          volume_fraction_2 = 0.5;
    std::array<ElasticMaterial, 2>  elastic;
    std::array<SizeDistribution, 2> sizes;
    std::uint64_t                   seed = 1;
    /// The upper punch starts at the height of this in-die relative
    /// density, or at the top of the deposit if that is higher [-].
    double initial_density = 0.42;
  };

  /// Mean volume of a log-normal sphere, 4/3 pi R_50^3 exp(9 sigma^2 / 2)
  /// (the cut-offs ignored) [m^3].
  double
  mean_sphere_volume(const SizeDistribution &d);

  /// Particles of each material among @p n for the bed's solid volume
  /// fraction of material 2.
  std::vector<std::size_t>
  material_counts(const TwoMaterialBed &bed, std::size_t n);

  /// Ballistic deposit of @p n particles of the bed into a die of side
  /// @p width.
  ParticleSystem
  deposit_bed(const TwoMaterialBed &bed, double width, std::size_t n);

  /// Height of the highest sphere top [m].
  double
  bed_top(const ParticleSystem &particles);

  /// The die of the bed with its upper punch at the initial density's
  /// height or at the deposit's top, whichever is higher.
  SquareDie
  starting_die(const TwoMaterialBed &bed, const ParticleSystem &deposit);

  /// Hertz against nonlocal at one density both formulations reached.
  struct FormulationDiscrepancy
  {
    double relative_density;
    /// Upper-punch load [N] and mean lateral reaction [N].
    double hertz_load, nonlocal_load, hertz_lateral, nonlocal_lateral;
    /// (nonlocal - hertz) / hertz where both are jammed and hertz > 0.
    std::optional<double> load_discrepancy, lateral_discrepancy;
  };

  /// The discrepancies at every density of @p hertz that @p nonlocal also
  /// reached (to 1e-9 relative).
  std::vector<FormulationDiscrepancy>
  formulation_discrepancies(const BedCompactionResult &hertz,
                            const BedCompactionResult &nonlocal);

  /// The cost of one residual of a formulation on a large bed.
  struct ResidualTiming
  {
    bool        nonlocal;
    std::size_t particles, candidates, loaded, incidences;
    /// Algorithm 1 sweeps from a cold start and per warm residual.
    unsigned int cold_sweeps;
    double       warm_sweeps;
    double       seconds_per_residual;
  };

  /**
   * Deposits @p n_particles of the bed in a die wide enough that the bed is
   * about as high as it is wide, compresses it affinely by 2 % of its
   * height, and times @p repetitions residuals of the Hertz and then the
   * nonlocal formulation, each from a warm start (tiny moves, as between
   * Newton iterates).
   */
  std::vector<ResidualTiming>
  time_bed_residuals(const TwoMaterialBed &bed,
                     std::size_t           n_particles,
                     int                   repetitions);
} // namespace compax::dem
