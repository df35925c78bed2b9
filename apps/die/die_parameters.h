#pragma once

#include "dem/die/die_compaction.h"
#include "dem/packing/ballistic_deposition.h"
#include "dem/solver/contact_model.h"

#include <deal.II/base/parameter_handler.h>

namespace compax::cli
{
  /// Everything `compax die` reads from its .prm, in the library's types.
  struct DieStudy
  {
    dem::DepositionParameters deposition;
    dem::ContactModel         model;
    dem::DieProtocol          protocol;
    dem::EquilibriumOptions   equilibrium;
    /// In-die relative density at which compaction stops [-].
    double final_density;
    /// Number of equal density steps from the packing to final_density.
    int compaction_steps;
    /// A branch checkpoint (checkpoints/branch-<k>.h5) to rerun that
    /// unloading branch from, instead of the whole study; empty: none.
    std::string rerun_branch_from;
    /// A compaction checkpoint (checkpoints/compaction.h5) to resume an
    /// interrupted run from; empty: none.
    std::string resume_from;
    /// The canonical text of the entries a compaction checkpoint must have
    /// been written with to be resumed (coupling::ArchiveIdentity).
    std::string resume_parameters;
    /// ... and those of a saved bed state (branch checkpoints,
    /// last_converged.h5): the particles, their materials and contacts.
    std::string state_parameters;
  };

  /// Declares the subsections Material, Material 2, Bonding, Packing,
  /// Protocol, Solver, Contact.
  void
  declare_die_parameters(dealii::ParameterHandler &prm);

  /// Reads and cross-checks them; throws InputError naming the entry.
  DieStudy
  get_die_study(dealii::ParameterHandler &prm);

  /// The compaction targets from the packing's relative density @p rho_0
  /// to the final density; throws InputError if that is not above it.
  void
  set_compaction_targets(DieStudy &study, double rho_0);
} // namespace compax::cli
