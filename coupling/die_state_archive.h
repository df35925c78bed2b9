#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/contact_model.h"

#include <string>

namespace compax::coupling
{
  /**
   * @name Single die bed states
   *
   * Archives that hold one bed of a die study (group "bed", save_bed())
   * with the canonical @p parameters of the state it depends on (contact
   * model and die, not the protocol): a branch checkpoint, from which one
   * unloading branch can be rerun with dem::DieStudyStart::branch(), and
   * the last converged state of a run that failed.
   */
  ///@{

  /// A bed on the compaction path at the unloading point of a branch.
  struct DieBranchState
  {
    dem::Bed bed;
    /// The branch (1, 2, ...).
    int branch = 0;
  };

  /// Writes checkpoints/branch-<k>.h5 (kind "die-branch") atomically.
  void
  write_die_branch_checkpoint(const std::string &file,
                              const std::string &parameters,
                              const dem::Bed    &bed,
                              int                branch);

  /// Reads what write_die_branch_checkpoint() wrote with these
  /// @p parameters; throws Hdf5ArchiveError or std::runtime_error (no
  /// branch number, inconsistent bed) with a one-line reason.
  DieBranchState
  read_die_branch_checkpoint(const std::string       &file,
                             const std::string       &parameters,
                             const dem::ContactModel &model);

  /// Writes last_converged.h5 (kind "die-state"): the state a failed run
  /// stopped at and, as attribute `failure`, why.
  void
  write_die_state(const std::string &file,
                  const std::string &parameters,
                  const dem::Bed    &bed,
                  const std::string &failure);
  ///@}
} // namespace compax::coupling
