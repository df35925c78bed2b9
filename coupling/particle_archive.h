#pragma once

#include "coupling/hdf5_archive.h"
#include "dem/particles/particle_system.h"
#include "dem/solver/contact_model.h"

#include <string>

namespace compax::coupling
{
  /**
   * Saves the particles of a bed or an RVE under `group` of an archive:
   * `positions` ({n, 3}), `radii` and `materials` (n each). The same
   * arrays in every archive that holds particles (save_bed(), save_rve()).
   */
  void
  save_particles(Hdf5ArchiveWriter         &archive,
                 const std::string         &group,
                 const dem::ParticleSystem &particles);

  /**
   * Restores the particles saved by save_particles(), checking that the
   * arrays agree in length and that every material and radius is one of
   * @p model. Throws std::runtime_error "<where>: <reason>", with
   * @p foreign_particle the reason for a particle @p model does not know
   * (each kind of archive keeps its own wording).
   */
  dem::ParticleSystem
  load_particles(const Hdf5ArchiveReader &archive,
                 const std::string       &group,
                 const dem::ContactModel &model,
                 const std::string       &where,
                 const std::string       &foreign_particle);
} // namespace compax::coupling
