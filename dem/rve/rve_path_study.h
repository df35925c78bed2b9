#pragma once

#include "dem/rve/elastic_moduli.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/nonlocal_rve_loading.h"
#include "dem/rve/periodic_bed.h"
#include "dem/rve/rve_loading.h"
#include "dem/rve/rve_measures.h"
#include "dem/solver/contact_model.h"

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace compax::dem
{
  /// The macroscopic strain paths of an RVE path study.
  enum class RveStrainPath
  {
    /// F = diag(1, 1, rho_0 / rho): die-like compaction along z.
    uniaxial,
    /// F = (rho_0 / rho)^(1/3) I.
    hydrostatic,
    /// F <- (I + eps_k) F for given strain increments eps_k.
    increments
  };

  /// What an RVE path study does: the path, its unloading, where tangents
  /// and finite-difference checks are taken, the solvers.
  struct RvePathStudyOptions
  {
    RveStrainPath path = RveStrainPath::uniaxial;
    /// Relative density at the end of loading (uniaxial, hydrostatic) [-].
    double target_density = 0.8;
    /// Loading steps of equal density increment (uniaxial, hydrostatic);
    /// the number of increments (increments).
    int steps = 25;
    /// Unload along the same path until the axial (uniaxial) or mean
    /// stress vanishes (increments: undo them in reverse order).
    bool unload = true;
    /// Logarithmic strain per unloading step (uniaxial, hydrostatic) [-].
    double unloading_step      = 5e-4;
    int    max_unloading_steps = 500;
    /// Strain increments of the increments path.
    std::vector<Eigen::Matrix3d> increments;

    /// Tangents every this many steps (0: only at the end of loading and
    /// of the path).
    int tangent_interval = 1;
    /// Finite-difference check of the condensed tangent every this many
    /// steps (0: never).
    int    fd_interval    = 0;
    double fd_strain_step = 1e-8;
    /// Equilibrium force tolerance of the finite-difference solves [-].
    double fd_force_tolerance = 1e-10;

    /// Elastic frictionless spheres (Hertz or nonlocal), stepped by
    /// NonlocalRveLoading, without tangents; empty: the bonded law.
    std::optional<NonlocalRveOptions> elastic;
    RveLoadingOptions                 loading;

    /// Stop once this step is done (0: run to the end), to be resumed from
    /// RvePathStudy::state().
    int stop_after = 0;
  };

  /// The loading options a cell for this path is packed with: elastic
  /// spheres are packed with the bonded law's elastic branch, virgin (a
  /// deposit compacted with frozen histories).
  RveLoadingOptions
  packing_loading(const RvePathStudyOptions &options);

  /// One converged state of the path (step 0: the initial state).
  struct RvePathStep
  {
    int  step      = 0;
    bool unloading = false;
    /// Solid volume over cell volume [-].
    double relative_density = 0.0;
    /// Logarithmic strain of F [-].
    Eigen::Matrix3d strain = Eigen::Matrix3d::Zero();
    /// Homogenized Cauchy stress (Love-Weber; the elastic law's for
    /// elastic spheres) [Pa], tension positive, as computed (not
    /// symmetrized).
    Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
    /// Coordination, rattlers, bonds (elastic spheres: the mechanical
    /// coordination only, rattler measures NaN).
    RveMeasures measures;
    /// How the step was solved; empty for the initial state.
    std::optional<RveStepResult> solve;
    /// Wall time of the step [s].
    double seconds = 0.0;
  };

  /// Tangents and moduli of a jammed state of the bonded law.
  struct RvePathModuli
  {
    int    step             = 0;
    bool   unloading        = false;
    double relative_density = 0.0;
    /// Condensed and affine consistent tangents (current branch) [Pa].
    CellTangents current;
    /// Condensed tangent of the unloading (elastic) branch [Pa].
    Matrix6d unloading_condensed = Matrix6d::Zero();
    /// Isotropic part of the symmetric unloading tangent.
    IsotropicModuli isotropic{};
    /// Its transversely isotropic constants about z; empty where the
    /// tangent is not positive definite (a barely jammed cell).
    std::optional<TransverselyIsotropicModuli> transversely_isotropic;
    /// Transversely isotropic parts of the symmetric current condensed and
    /// affine tangents (the Cauchy-stress tangents carry a non-symmetric
    /// -sigma tr(eps) term).
    Matrix6d condensed_projection = Matrix6d::Zero();
    Matrix6d affine_projection    = Matrix6d::Zero();
    /// |C - C_fd| / |C_fd| of the finite-difference check (NaN: not
    /// checked, or skipped).
    double fd_error = std::numeric_limits<double>::quiet_NaN();
    /// Wall time of the current-branch tangents [s].
    double seconds = 0.0;
  };

  /// Timings of one run [s].
  struct RvePathTimings
  {
    double steps         = 0.0;
    int    n_steps       = 0;
    double tangents      = 0.0; ///< condensed + affine, current branch
    int    n_tangents    = 0;
    double fd_tangents   = 0.0;
    int    n_fd_tangents = 0;
    double total         = 0.0;
  };

  /// What one run() computed.
  struct RvePathResult
  {
    /// The states of this run (a resumed run: from the first new step).
    std::vector<RvePathStep>   steps;
    std::vector<RvePathModuli> moduli;
    RvePathTimings             timings;
    /// False if a step did not converge (or threw): the cell is then the
    /// last converged state, and `failure` says why.
    bool        converged = true;
    std::string failure;
    /// Stopped after RvePathStudyOptions::stop_after.
    bool stopped = false;
  };

  /**
   * Where a path stands: the cell and what the rest of the path needs. A
   * state built from a cell alone starts the path; the state of a stopped
   * study (or one rebuilt from its saved numbers) resumes it.
   */
  struct RvePathState
  {
    PeriodicBed bed;
    /// Whether the initial state (step 0) has been recorded.
    bool started        = false;
    int  loading_done   = 0;
    int  unloading_done = 0;
    /// Relative density of step 0 [-].
    double initial_density = 0.0;
    /// Whether a recorded state carried the jamming pressure (jamming is
    /// sticky on the bonded path).
    bool jammed = false;
    /// The last recorded state: unloading, its sigma_zz and mean pressure
    /// -tr(sigma)/3 [Pa] (whether unloading is complete).
    bool   unloading     = false;
    double axial_stress  = 0.0;
    double mean_pressure = 0.0;
    /// F at the end of loading (unloading starts from it).
    Eigen::Matrix3d loaded_deformation = Eigen::Matrix3d::Identity();

    int
    step() const
    {
      return loading_done + unloading_done;
    }
  };

  /// A converged step, before its tangents (for a progress line).
  struct RvePathStepEvent
  {
    const RvePathStep    &step;
    const RvePathState   &state;
    const RvePathTimings &timings;
  };

  /**
   * A recorded state with its tangents, the cell as a checkpoint holds it,
   * before the next step starts afresh: where snapshots and checkpoints
   * are taken.
   */
  struct RvePathStateEvent
  {
    const RvePathState  &state;
    const RvePathResult &result;
    /// The initial state of a fresh path.
    bool initial = false;
    /// The last step of loading or of unloading.
    bool end_of_stage = false;
    /// The study stops after this state (stop_after).
    bool stopping = false;
  };

  /// Progress reports of a run (each may be empty). An exception of type
  /// std::runtime_error thrown by one ends the run as a failed step.
  struct RvePathObserver
  {
    std::function<void(const RvePathStepEvent &)>  step;
    std::function<void(const RvePathStateEvent &)> state;
    /// Remarks, e.g. a skipped finite-difference check.
    std::function<void(const std::string &)> note;
  };

  /**
   * The RVE strain-path study: drives a periodic cell along a macroscopic
   * strain path (loading, then optionally unloading), recording per step
   * the strain, stress, density and microstructure and, where asked, the
   * condensed and affine tangents with their moduli and a
   * finite-difference check. Every step starts afresh from the state a
   * checkpoint would hold (contacts rebuilt, loading and tangent
   * calculators new): the results depend neither on where tangents or
   * checkpoints were taken nor on where a run was stopped and resumed.
   */
  class RvePathStudy
  {
  public:
    RvePathStudy(ContactModel        model,
                 RvePathStudyOptions options,
                 RvePathState        state);

    /// Runs the path from the state to its end (or to stop_after). The
    /// state is left where the run ended: a study built from state()
    /// (e.g. with stop_after cleared) continues the path exactly as an
    /// uninterrupted run would.
    RvePathResult
    run(const RvePathObserver &observer = {});

    /// Where the path stands (after run(): to resume from).
    const RvePathState &
    state() const
    {
      return state_;
    }

    const ContactModel &
    model() const
    {
      return model_;
    }

    const RvePathStudyOptions &
    options() const
    {
      return options_;
    }

  private:
    ContactModel        model_;
    RvePathStudyOptions options_;
    RvePathState        state_;
  };
} // namespace compax::dem
