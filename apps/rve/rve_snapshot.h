#pragma once

#include "dem/rve/periodic_bed.h"

#include <filesystem>
#include <string>

namespace compax::cli
{
  /**
   * Writes the particles of a periodic cell as a VTK XML unstructured grid
   * of vertices (.vtu) with the point data of the die's snapshots (radius,
   * material, coordination, net_force, mean_contact_force,
   * max_<variable> of each declared internal variable, bonds), the positions
   * wrapped into the cell (the cell keeps them unwrapped).
   * dem/io/particle_vtu.h writes a die Bed, whose contacts join unwrapped
   * positions without images, hence this writer; the collection file is
   * dem::write_pvd's.
   */
  void
  write_rve_vtu(const std::filesystem::path &file, const dem::PeriodicBed &bed);

  /// The snapshot of a step, relative to the run folder (checkpoints list
  /// snapshots by step).
  std::string
  snapshot_name(int step);
} // namespace compax::cli
