#pragma once

#include "coupling/database_validation.h"
#include "coupling/rve_database.h"
#include "dem/solver/contact_model.h"
#include "fem/dpc_table.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace compax::coupling
{
  /// What an RVE database study does beyond its paths.
  struct RveDatabaseStudyOptions
  {
    DatabaseSpec spec;
    /// Drive the fitted law along every path and measure its error; off,
    /// the study ends with the fit (what a multiscale tablet needs).
    bool validate = true;
    /// With validate: also run every path on a second packing (seed + 1),
    /// not used in the fit, to measure the law on it and the RVE's own
    /// packing-to-packing scatter (the yardstick of the law's error).
    /// Doubles the run time.
    bool held_out_packing = true;
    /// Stop (RveDatabase::stopped, no fit) after this many completed
    /// branches in all, if more remain; 0: run to the end.
    int stop_after_branches = 0;
  };

  /// One comparison of two responses along the database paths.
  struct DatabaseComparison
  {
    /// dpc_vs_rve, dpc_vs_held_out_packing or rve_packing_scatter.
    std::string            name;
    std::vector<PathError> errors;
    /// Pooled relative stress errors over the training paths and over
    /// the held-out (radial) paths (pooled_stress_error) [-].
    double training_error = 0.0;
    double held_out_error = 0.0;
  };

  /// The measured error of the fitted law.
  struct DatabaseValidationResult
  {
    /// The database with the fitted law's stresses (drive_along_database);
    /// empty if driving the law failed.
    std::optional<RveDatabase> law;
    /// dpc_vs_rve, then with a held-out packing dpc_vs_held_out_packing and
    /// rve_packing_scatter.
    std::vector<DatabaseComparison> comparisons;
  };

  /// How far a study got.
  enum class RveDatabaseOutcome
  {
    /// Database, fit and (if asked) validation done.
    complete,
    /// Stopped as asked after stop_after_branches: database only.
    stopped,
    /// An RVE path did not converge: nothing but the failure.
    database_failed,
    /// Database and fit done; driving the law or the held-out packing
    /// failed (validation holds what was done).
    validation_failed
  };

  /// What an RVE database study computed.
  struct RveDatabaseStudyResult
  {
    RveDatabaseOutcome outcome = RveDatabaseOutcome::complete;
    /// Why a stage failed (empty otherwise).
    std::string failure;
    RveDatabase database;
    /// The Drucker-Prager Cap fitted to it, one row per branch, and the
    /// remarks of the fit (fit_drucker_prager_cap).
    std::vector<DpcFitRow>   fit;
    std::vector<std::string> notes;
    DatabaseValidationResult validation;
    /// Wall time of the database and of the validation [s].
    double database_seconds   = 0.0;
    double validation_seconds = 0.0;
  };

  /// The fitted rows as the tablet model's DPC table (validated; throws
  /// std::invalid_argument if they do not form one).
  fem::DpcTable
  to_dpc_table(const std::vector<DpcFitRow> &rows);

  /**
   * The RVE database study of `compax database` and of the multiscale
   * tablet: builds the RVE response database (build_rve_database), fits
   * the density-dependent Drucker-Prager Cap to it, and measures the
   * fitted law's stress error along the training and held-out paths, on
   * the fitted packing and on a held-out one. Computes in memory and never
   * prints: progress lines go to on_progress, completed branches to
   * on_branch_done (for checkpoints); the caller writes the files.
   */
  class RveDatabaseStudy
  {
  public:
    RveDatabaseStudy(dem::ContactModel model, RveDatabaseStudyOptions options);

    /// Runs the study (continuing @p resume if given).
    RveDatabaseStudyResult
    run(const DatabaseResume *resume = nullptr) const;

    /// Progress lines: one per compaction step and per finished path, and
    /// the start of the held-out packing.
    std::function<void(const std::string &)> on_progress;
    /// Called after each completed branch with the database so far and
    /// the compaction cell (DatabaseControl::branch_done).
    std::function<void(const RveDatabase &, const dem::PeriodicBed &)>
      on_branch_done;

  private:
    void
    validate(const RveDatabase        &database,
             const fem::MaterialModel &law,
             DatabaseValidationResult &out) const;

    dem::ContactModel       model;
    RveDatabaseStudyOptions options;
  };
} // namespace compax::coupling
