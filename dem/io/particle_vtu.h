#pragma once

#include "dem/solver/bed.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace compax::dem
{
  /**
   * Writes the particles of a bed as a VTK XML unstructured grid of vertices
   * (.vtu), for ParaView: glyph them with spheres scaled by "radius". Point
   * data: radius [m], material, coordination (number of loaded particle
   * contacts), net contact force magnitude on the particle [N], largest
   * plastic contact radius a_p among its contacts [m], number of intact
   * solid bridges (a_B > 0), and the mean normal force of its contacts [N].
   */
  void
  write_particles_vtu(const std::filesystem::path &file, const Bed &bed);

  /**
   * A ParaView collection (.pvd) of snapshots; each entry is (time-like
   * value, file name relative to the .pvd). Rewritten whole on each call so
   * an interrupted run leaves a valid file.
   */
  void
  write_pvd(const std::filesystem::path                       &file,
            const std::vector<std::pair<double, std::string>> &snapshots);
} // namespace compax::dem
