#include "coupling/rve_database_study.h"

#include "fem/drucker_prager_cap.h"

#include <deal.II/base/timer.h>

#include <stdexcept>
#include <utility>

namespace compax::coupling
{
  namespace
  {
    DatabaseComparison
    compare(std::string        name,
            const RveDatabase &reference,
            const RveDatabase &other)
    {
      return {std::move(name),
              path_errors(reference, other),
              pooled_stress_error(reference, other, true),
              pooled_stress_error(reference, other, false)};
    }
  } // namespace

  fem::DpcTable
  to_dpc_table(const std::vector<DpcFitRow> &rows)
  {
    fem::DpcTable table;
    for (const DpcFitRow &r : rows)
      table.add_row(r.relative_density,
                    r.cohesion,
                    r.friction_angle_deg,
                    r.cap_eccentricity,
                    r.cap_pressure,
                    r.youngs_modulus,
                    r.poisson_ratio);
    table.validate();
    return table;
  }

  RveDatabaseStudy::RveDatabaseStudy(dem::ContactModel       model,
                                     RveDatabaseStudyOptions options)
      : model(std::move(model))
      , options(std::move(options))
  {
  }

  RveDatabaseStudyResult
  RveDatabaseStudy::run(const DatabaseResume *resume) const
  {
    const dealii::Timer    database_timer;
    RveDatabaseStudyResult out;
    const auto             progress = [this](const std::string &line) {
      if (on_progress)
        on_progress(line);
    };
    DatabaseControl control;
    control.resume              = resume;
    control.stop_after_branches = options.stop_after_branches;
    control.branch_done         = on_branch_done;
    try
      {
        out.database
          = build_rve_database(options.spec, model, progress, control);
      }
    catch (const std::runtime_error &e)
      {
        out.outcome = RveDatabaseOutcome::database_failed;
        out.failure = e.what();
        return out;
      }
    out.database_seconds = database_timer.wall_time();
    if (out.database.stopped)
      {
        out.outcome = RveDatabaseOutcome::stopped;
        return out;
      }

    out.fit = fit_drucker_prager_cap(out.database, &out.notes);
    if (!options.validate)
      return out;
    const dealii::Timer         validation_timer;
    const fem::DruckerPragerCap law(to_dpc_table(out.fit));
    try
      {
        validate(out.database, law, out.validation);
      }
    catch (const std::runtime_error &e)
      {
        out.outcome = RveDatabaseOutcome::validation_failed;
        out.failure = e.what();
      }
    out.validation_seconds = validation_timer.wall_time();
    return out;
  }

  void
  RveDatabaseStudy::validate(const RveDatabase        &db,
                             const fem::MaterialModel &law,
                             DatabaseValidationResult &out) const
  {
    out.law = with_stresses(db, drive_along_database(db, law));
    out.comparisons.push_back(compare("dpc_vs_rve", db, *out.law));
    if (!options.held_out_packing)
      return;
    DatabaseSpec held_out_spec = options.spec;
    ++held_out_spec.packing.seed;
    if (on_progress)
      on_progress("held-out packing (seed "
                  + std::to_string(held_out_spec.packing.seed) + ")");
    const RveDatabase held = build_rve_database(held_out_spec, model, {});
    const RveDatabase held_law
      = with_stresses(held, drive_along_database(held, law));
    out.comparisons.push_back(
      compare("dpc_vs_held_out_packing", held, held_law));
    out.comparisons.push_back(compare("rve_packing_scatter", db, held));
  }
} // namespace compax::coupling
