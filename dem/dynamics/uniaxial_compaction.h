#pragma once

#include "dem/dynamics/explicit_dem.h"
#include "dem/packing/random_source.h"

#include <cstdint>
#include <functional>
#include <memory>

namespace compax::dem
{
  /// The representative volume element: a cube periodic in x and y
  /// between two plates, filled to a packing density (Giannis 2021 §4.1).
  struct RveSpec
  {
    /// Edge of the cube [m] (paper: 0.6, 0.8, 1.0, 1.4 mm).
    double cell_size = 0.6e-3;
    /// Solid fraction after growth [-] (paper: about 0.59).
    double packing_density = 0.59;
    /// Radii (number distribution, with cut-offs).
    SizeDistribution sizes;
    /// Nonzero: this many particles, the cube scaled to the density.
    std::size_t particle_count = 0;
    /// Seed of the insertion.
    std::uint64_t seed = 1;
    /// Radii at insertion, as a fraction of the final radii [-].
    double initial_scale = 0.5;
  };

  /// Times and targets of the growth, compaction and decompression.
  struct CompactionProtocol
  {
    /// Duration of the growth from initial_scale to full radii [s].
    double growth_time = 2e-4;
    /// Free relaxation after the growth [s].
    double relaxation_time = 1e-4;
    /// Engineering strain rate of the top plate, both ways [1/s].
    double strain_rate = 50.0;
    /// Loading stops at this strain (z, compression positive) [-] ...
    double target_strain = 0.57;
    /// ... or at this plate stress, if positive [Pa].
    double target_stress = 0.0;
    /// Decompress after loading until the plate stress vanishes.
    bool decompress = true;
    /// A record every this much strain (and at the turning points) [-].
    double output_strain_interval = 0.005;
  };

  /// One line of the stress-strain output.
  struct CompactionRecord
  {
    double time;             ///< since the start of compaction [s]
    int    stage;            ///< 1 compression, 2 decompression
    double strain;           ///< (H_0 - H)/H_0, compression positive [-]
    double stress_zz;        ///< plate stress, compr. + [Pa] (loading:
                             ///< mean over the output interval)
    double stress_zz_bulk;   ///< -(Love-Weber sigma_zz) of the particles [Pa]
    double relative_density; ///< sum V_i / (L_x L_y H) [-]
    double kinetic_energy;   ///< [J]
    double elastic_energy;   ///< [J] (ExplicitDem::elastic_energy)
    double coordination;     ///< (2 N_pp + N_pw) / N [-]
    double mean_pressure;    ///< -mean p_i of the particles, compr. + [Pa]
    double time_step;        ///< [s]
  };

  /// Progress of a run for the screen.
  struct CompactionProgress
  {
    const char   *phase;    ///< "growth", "relaxation", "compression", ...
    double        fraction; ///< of the phase done, [0, 1]
    double        strain;
    double        stress_zz;
    std::uint64_t steps;
  };

  /// Totals of a run.
  struct CompactionSummary
  {
    std::size_t   particles       = 0;
    double        initial_density = 0.0; ///< after growth [-]
    double        peak_strain     = 0.0;
    double        peak_stress     = 0.0; ///< [Pa]
    double        residual_strain = 0.0; ///< where unloading reached 0
    std::uint64_t steps           = 0;   ///< all phases
    double        particle_steps  = 0.0; ///< sum over steps of N
    double        wall_seconds    = 0.0; ///< all phases
  };

  /**
   * Strain-driven uniaxial compaction of an RVE (Giannis 2021 §4.1):
   * random insertion of shrunk particles (insert_random), growth to the
   * packing density with the conventional elastic frictionless law (to
   * build the packing without pre-straining the plastic contacts), a
   * relaxation, then the material's law and friction with fresh contact
   * histories; the top plate moves down at a constant engineering strain
   * rate to the target strain or stress, then back up until the plate
   * stress vanishes.
   */
  class UniaxialCompaction
  {
  public:
    UniaxialCompaction(const DemMaterial      &material,
                       const DynamicsSettings &settings,
                       const RveSpec          &rve);

    /// A deep copy (e.g. of a prepared packing, to compact it with
    /// several laws).
    UniaxialCompaction(const UniaxialCompaction &other);

    using RecordCallback   = std::function<void(const CompactionRecord &)>;
    using ProgressCallback = std::function<void(const CompactionProgress &)>;

    /// Inserts, grows and relaxes the packing.
    void
    prepare(const CompactionProtocol &protocol,
            const ProgressCallback   &progress = {});

    /// Compaction (and decompression) of the prepared packing, with the
    /// law currently set in dem() (the material's after prepare()).
    CompactionSummary
    compact(const CompactionProtocol &protocol,
            const RecordCallback     &record,
            const ProgressCallback   &progress = {});

    ExplicitDem &
    dem()
    {
      return *system;
    }

    /// Edges of the cell [m] (scaled if a particle count was given).
    const Eigen::Vector3d &
    box() const
    {
      return box_lengths;
    }

  private:
    CompactionRecord
    measure(int stage, double strain, double stress);

    DemMaterial                  material;
    DynamicsSettings             settings;
    RveSpec                      rve;
    Eigen::Vector3d              box_lengths;
    std::unique_ptr<ExplicitDem> system;
    std::vector<double>          full_radii;
    CompactionSummary            summary;
  };
} // namespace compax::dem
