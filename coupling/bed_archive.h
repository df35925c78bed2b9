#pragma once

#include "coupling/hdf5_archive.h"
#include "dem/solver/bed.h"
#include "dem/solver/contact_model.h"

#include <string>

namespace compax::coupling
{
  /**
   * Saves a bed state into an HDF5 archive under `group`: particle
   * positions, radii and materials, the die walls, the Verlet skin, and the
   * ContactHistory slots of every contact that has any history. The
   * contact laws are not stored: they follow from the materials and the
   * ContactModel when the bed is loaded.
   */
  void
  save_bed(Hdf5ArchiveWriter &archive,
           const std::string &group,
           const dem::Bed    &bed);

  /// Restores a bed saved by save_bed(); the contact list is rebuilt with
  /// the saved histories merged in, so positions and internal variables are
  /// exactly those saved.
  dem::Bed
  load_bed(const Hdf5ArchiveReader &archive,
           const std::string       &group,
           const dem::ContactModel &model);
} // namespace compax::coupling
