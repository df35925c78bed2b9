#pragma once

#include "coupling/rve_database.h"
#include "coupling/rve_database_study.h"
#include "dem/solver/contact_model.h"
#include "fem/drucker_prager_cap.h"

#include <deal.II/base/mpi.h>

#include <functional>
#include <memory>
#include <string>

namespace compax::coupling
{
  /// What the rank that builds a multiscale database reports: the rest
  /// only wait for its table, so they report nothing.
  struct MultiscaleDatabaseObserver
  {
    /// Before the database is built (e.g. a header line).
    std::function<void()> started;
    /// Progress lines of the database (RveDatabaseStudy::on_progress).
    std::function<void(const std::string &)> progress;
    /// The database and its fit, e.g. to write their files.
    std::function<void(const RveDatabaseStudyResult &)> built;
  };

  /**
   * The `multiscale-database` material of a tablet: the Drucker-Prager Cap
   * fitted to the RVE response database of @p spec (an RveDatabaseStudy
   * without validation). Collective on @p comm: rank 0 alone builds the
   * database and calls @p observer, so the files are written and the
   * progress printed once; it broadcasts the fitted table, so every rank
   * returns the same material, by construction rather than by every rank
   * repeating the same arithmetic (which would also cost each rank the
   * database). Throws std::runtime_error on every rank when the RVE does
   * not converge on rank 0.
   */
  std::shared_ptr<fem::DruckerPragerCap>
  make_multiscale_database_material(const DatabaseSpec               &spec,
                                    const dem::ContactModel          &model,
                                    MPI_Comm                          comm,
                                    const MultiscaleDatabaseObserver &observer
                                    = {});
} // namespace compax::coupling
