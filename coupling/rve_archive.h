#pragma once

#include "coupling/hdf5_archive.h"
#include "dem/rve/periodic_bed.h"
#include "dem/solver/contact_model.h"

#include <optional>
#include <string>

namespace compax::coupling
{
  /**
   * Saves an RVE state under `group` of an archive: particle positions
   * (unwrapped), radii and materials, the lattice H, the reference lattice
   * H_0, the deformation gradient F, the periodicity, the Verlet skin and
   * every contact of the list as (i, j, image, its ContactHistory slots). The
   * contact laws are not stored: they follow from the materials, radii and
   * the ContactModel when the state is loaded.
   */
  void
  save_rve(Hdf5ArchiveWriter      &archive,
           const std::string      &group,
           const dem::PeriodicBed &bed);

  /**
   * Restores a state saved by save_rve(). The saved contacts become the
   * list that a rebuild at the saved positions merges with the candidates,
   * so positions, lattice and every internal variable are exactly those
   * saved, and the list equals the one the original cell gets from
   * contacts.rebuild() at the same state (a restart repeats the original
   * bitwise when the original rebuilds its list at the checkpoint, as
   * `compax rve` does; otherwise to the equilibrium tolerance).
   * Throws Hdf5ArchiveError or std::runtime_error on a malformed group.
   */
  dem::PeriodicBed
  load_rve(const Hdf5ArchiveReader &archive,
           const std::string       &group,
           const dem::ContactModel &model);

  /// Writes an archive of kind "rve-state" holding one RVE state (group
  /// "rve") atomically: a crash leaves any previous file at @p path
  /// untouched.
  void
  save_rve(const std::string      &path,
           const dem::PeriodicBed &bed,
           const std::string      &parameters = "");

  /// Reads the RVE state of an archive written by save_rve(path, bed),
  /// checking its @p parameters if given; throws Hdf5ArchiveError if it is
  /// not one.
  dem::PeriodicBed
  load_rve(const std::string                &path,
           const dem::ContactModel          &model,
           const std::optional<std::string> &parameters = std::nullopt);
} // namespace compax::coupling
