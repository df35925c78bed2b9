#pragma once

#include "fem/material_model.h"
#include "fem/tablet_process.h"

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace compax::coupling
{
  /// Where a tablet study writes, and how it checkpoints and resumes.
  struct TabletStudyOptions
  {
    /// Output folder (the same path on every rank); empty: no files, the
    /// result is in memory only (no checkpoints then).
    std::filesystem::path folder;
    /// tablet.pvd with tablet_NNNN.pvtu/vtu fields.
    bool write_fields = true;
    /// With write_fields: also tablet_NNNN.h5 listed by tablet.xdmf.
    bool write_hdf5 = true;
    /// Fields every this many steps (> 0; and at the end of every stage).
    unsigned int field_interval = 20;
    /// A checkpoint (folder/checkpoint) every this many steps and when a
    /// step does not converge; 0: none.
    unsigned int checkpoint_interval = 0;
    /// Output folder of an earlier run of the same cycle to continue from
    /// its checkpoint; empty: start afresh.
    std::filesystem::path resume_from;
    /// The canonical text of the parameters a checkpoint is written with
    /// and must match on resume.
    std::string parameters;
  };

  /// Extremes of a tablet cycle.
  struct TabletSummary
  {
    double max_upper_pressure  = 0.0;
    double density_at_max      = 0.0;
    double density_unloaded    = 0.0;
    double residual_wall       = 0.0;
    double density_out_of_die  = 0.0;
    double peak_ejection_force = 0.0;
    /// tr(sigma) / 3 averaged over the tablet at the end of ejection [Pa].
    double mean_stress_out_of_die = 0.0;
    bool   ejected                = false;

    /// Takes the next step of the cycle into account (punch area @p area).
    void
    add(const fem::TabletStep &step, double area);
  };

  /// Mean die-wall pressure of @p forces (0 without wall contact) [Pa].
  double
  die_wall_pressure(const fem::TabletForces &forces);

  /// Where a running study stands after a converged step.
  struct TabletProgress
  {
    fem::TabletStep step;
    /// Steps of the whole cycle.
    unsigned int n_steps = 0;
    /// Upper punch force over the punch area [Pa].
    double upper_punch_pressure = 0.0;
    double die_wall_pressure    = 0.0;
    /// Wall time since the run (or its resumption) started, and the
    /// estimate of what is left [s].
    double elapsed = 0.0;
    double left    = 0.0;
  };

  /// Where the time of an FE2 run went, summed over the ranks.
  struct TabletFe2Report
  {
    unsigned long long solves = 0, continuations = 0, failures = 0;
    /// RVE time on all ranks and on the busiest one, the run's wall time,
    /// and the slowest rank's pool consolidation at start-up [s].
    double seconds_all_ranks = 0.0, seconds_busiest_rank = 0.0,
           wall_seconds = 0.0, pool_seconds = 0.0;
    /// The floor's share of the final mean stress, tr / 3 (the RVEs carry
    /// the rest) [Pa].
    double floor_mean_stress = 0.0;
  };

  /// What a tablet study gives back, on every rank.
  struct TabletStudyResult
  {
    /// False if a step did not converge; history ends at the last good one.
    bool   converged  = false;
    double punch_area = 0.0;
    /// Every step from the initial state on (replayed ones of a resume
    /// included): the rows of tablet.csv.
    std::vector<fem::TabletStep> history;
    TabletSummary                summary;
    /// The step a resumed run continued after (0: started afresh).
    unsigned int resumed_after = 0;
    /// Only for an FE2 material (coupling::RveMaterial).
    std::optional<TabletFe2Report> fe2;
  };

  /// Header and one row of tablet.csv (12 significant digits).
  void
  write_tablet_csv_header(std::ostream &out);
  void
  write_tablet_csv_row(std::ostream          &out,
                       const fem::TabletStep &step,
                       double                 area);

  /**
   * A tableting cycle (compaction, unloading, ejection) of a compact with
   * its outputs: tablet.csv, field output, checkpoints and resume. The
   * library form of `compax tablet`, so that programs and other studies
   * run it without the command line; progress goes to on_step, not to a
   * stream. Collective on the communicator.
   */
  template <int dim>
  class TabletStudy
  {
  public:
    /// Builds the solver (and measures the initial volume).
    TabletStudy(const fem::TabletSolverSettings          &settings,
                const fem::TabletProcess                 &process,
                std::shared_ptr<const fem::MaterialModel> material,
                TabletStudyOptions                        options,
                MPI_Comm                                  comm);

    /**
     * Runs the cycle (once), after resuming from options.resume_from if
     * given. Throws TabletResumeError (coupling/tablet_checkpoint.h) if that
     * checkpoint cannot be resumed, on every rank.
     */
    TabletStudyResult
    run();

    const fem::TabletSolver<dim> &
    solver() const
    {
      return tablet;
    }

    /// Volume of the compact as filled [m^3].
    double
    initial_volume() const
    {
      return volume0;
    }

    /// Called on every rank after each converged step (not the replayed
    /// ones).
    std::function<void(const TabletProgress &)> on_step;
    /// Called on every rank with the last replayed step when a run resumes.
    std::function<void(const fem::TabletStep &)> on_resume;

  private:
    double
    record(const fem::TabletStep &step);
    void
    write_fields(const fem::TabletStep &step);
    void
    write_pvd() const;
    void
    checkpoint();
    unsigned int
    resume();
    std::optional<TabletFe2Report>
    fe2_report(double wall_seconds) const;

    fem::TabletSolver<dim>                      tablet;
    fem::TabletProcess                          process;
    std::shared_ptr<const fem::MaterialModel>   material;
    TabletStudyOptions                          options;
    MPI_Comm                                    comm;
    bool                                        root;
    double                                      volume0;
    std::ofstream                               csv;
    std::vector<std::pair<double, std::string>> pvd;
    std::vector<dealii::XDMFEntry>              xdmf;
    TabletStudyResult                           result;
    /// The step fields were written at last, the stage and the step seen
    /// last: fields go out at the end of every stage.
    unsigned int     last_written = 0;
    fem::TabletStage previous     = fem::TabletStage::compaction;
    fem::TabletStep  last;
  };
} // namespace compax::coupling
