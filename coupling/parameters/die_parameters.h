#pragma once

#include "dem/die/die_study.h"
#include "dem/packing/ballistic_deposition.h"
#include "dem/solver/contact_model.h"

#include <deal.II/base/parameter_handler.h>

namespace compax::coupling
{
  /// Everything `compax die` reads from its .prm: the study in the
  /// library's types, and where it starts from.
  struct DieInput
  {
    dem::ContactModel    model;
    dem::DieStudyOptions study;
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
  DieInput
  get_die_input(dealii::ParameterHandler &prm);

  /// The compaction targets from the packing's relative density @p rho_0
  /// to the final density; throws InputError if that is not above it.
  void
  set_compaction_targets(dem::DieStudyOptions &study, double rho_0);

  /// Throws the InputError of a final density not above the packing's
  /// @p packing_density.
  [[noreturn]] void
  reject_final_density(const dem::DieStudyOptions &study,
                       double                      packing_density);

  /// Runs @p action (which may build or run a dem::DieStudy) and turns a
  /// dem::DieTargetError into the InputError naming the final density.
  template <typename Action>
  auto
  naming_final_density(const dem::DieStudyOptions &study, Action &&action)
  {
    try
      {
        return action();
      }
    catch (const dem::DieTargetError &e)
      {
        reject_final_density(study, e.packing_density);
      }
  }
} // namespace compax::coupling
