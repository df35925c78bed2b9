#pragma once

#include "coupling/dpc_calibration.h"
#include "coupling/elastic_moduli.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"
#include "dem/rve/rve_packing.h"

#include <functional>
#include <string>
#include <vector>

namespace compax::coupling
{
  /// The strain paths of an RVE response database.
  struct DatabaseSpec
  {
    dem::PeriodicPackingSpec packing;
    dem::RveLoadingOptions   loading;
    /// A deposited packing denser than packing.relative_density: rejected
    /// (dem::DepositDensityError) or compacted from its own density.
    dem::DenserDeposit denser_deposit = dem::DenserDeposit::reject;
    /// Relative density at which uniaxial compaction stops [-].
    double final_density = 0.85;
    /// Axial logarithmic strain per compaction step [-].
    double strain_step = 0.01;
    /// Densities at which the compaction path branches into unloading and
    /// shear probes [-], increasing.
    std::vector<double> branch_densities = {0.70, 0.75, 0.80, 0.85};
    /// Engineering shear strain gamma_xz of each shear probe [-] ...
    double shear_strain = 0.04;
    /// ... applied in this many steps.
    int shear_steps = 20;
    /// Volumetric compression applied before the second shear probe [-],
    /// so that the two probes fail at different pressures.
    double confinement_strain = 0.004;
    /// Ratios eps_rr / eps_zz of the radial-strain probes run from each
    /// loaded branch state (0 would repeat uniaxial strain, 1 is
    /// hydrostatic, -0.5 isochoric triaxial-like compression); none of them
    /// enters the fit, so they are held-out paths of the continuum law.
    std::vector<double> radial_ratios = {-0.5, 0.5, 1.0};
    /// Axial compressive logarithmic strain of each radial probe [-] ...
    double radial_strain = 0.02;
    /// ... applied in this many steps.
    int radial_steps = 8;
  };

  /// One equilibrated state along a database path.
  struct DatabaseRow
  {
    /// -1 on the compaction path, else the branch index.
    int branch;
    /// compaction, unloading, shear, confinement, confined_shear or
    /// radial_<eps_rr/eps_zz> (e.g. radial_0.50).
    std::string path;
    double      relative_density;
    /// Engineering shear strain of a probe (0 elsewhere) [-].
    double        shear_strain;
    dem::Vector6d stress; ///< Love-Weber Cauchy stress, Voigt [Pa]
    /// Macroscopic deformation gradient F of the cell (from the packing).
    Eigen::Matrix3d deformation = Eigen::Matrix3d::Identity();
    /// Index of the row this state was reached from (-1 for the first):
    /// the rows form a tree whose edges are the strain increments
    /// F_row F_parent^-1, along which a continuum law can be driven.
    int parent = -1;
  };

  /// Whether a path's rows enter the fit of the continuum law (compaction,
  /// unloading, confinement and the shear probes) or are held out
  /// (radial-strain probes).
  bool
  is_training_path(const std::string &path);

  /// What one branch yields.
  struct DatabaseBranch
  {
    double        relative_density; ///< at the start of unloading [-]
    dem::Vector6d loaded_stress;    ///< [Pa]
    double        unloaded_density; ///< after axial unloading [-]
    /// Isotropic projection of (the symmetric part of) the condensed
    /// tangent of the unloaded cell, where every contact is on its elastic
    /// branch: the elastic moduli of the compact. (At the loaded state the
    /// solid bridges stiffen a contact within a fraction of a micrometre of
    /// unloading, so the one-sided tangent there is not representative.)
    IsotropicModuli elastic;
    /// Shear strength of the probe from the unloaded state and of the
    /// confined one: mean (p, q) over the second half of each probe [Pa].
    StressInvariants shear_failure;
    StressInvariants confined_shear_failure;
  };

  /// A database: every path row and the branch summaries.
  struct RveDatabase
  {
    std::vector<DatabaseRow>    rows;
    std::vector<DatabaseBranch> branches;
    /// True if the run stopped as asked before its last branch.
    bool stopped = false;
  };

  /// Where an interrupted database run continues: the rows and branches
  /// done so far and the compaction cell at the last completed branch.
  struct DatabaseResume
  {
    RveDatabase      database;
    dem::PeriodicBed bed;
  };

  /// Checkpointing and stopping of a database run.
  struct DatabaseControl
  {
    /// Continue this run instead of starting from a new packing.
    const DatabaseResume *resume = nullptr;
    /// Called after each completed branch with the database so far and
    /// the compaction cell (e.g. to write a checkpoint). The run then
    /// refreshes the cell's contact list and its solver state, as a run
    /// resumed from that point does, so a resumed run repeats an
    /// uninterrupted one exactly.
    std::function<void(const RveDatabase &, const dem::PeriodicBed &)>
      branch_done;
    /// Stop (RveDatabase::stopped) after this many completed branches in
    /// all, if more remain; 0: run to the end.
    int stop_after_branches = 0;
  };

  /// p and q of a Voigt stress (tension positive) [Pa].
  StressInvariants
  invariants(const dem::Vector6d &stress);

  /**
   * Builds an RVE response database: a periodic packing compacted in
   * uniaxial strain (die-like) to the final density; at each branch
   * density a copy is unloaded axially until it carries no axial stress,
   * and two copies of the unloaded cell are sheared at constant volume
   * (gamma_xz), the second after a small volumetric compression, to find
   * the stress where the compact fails in shear; from the loaded state,
   * radial-strain probes (eps_xx = eps_yy = k eps_zz for each ratio k).
   * Progress lines (one per step of compaction, one per finished path)
   * go to `progress` (may be empty). `control` resumes, checkpoints and
   * stops the run.
   */
  RveDatabase
  build_rve_database(const DatabaseSpec                     &spec,
                     const dem::ContactModel                &model,
                     const std::function<void(std::string)> &progress = {},
                     const DatabaseControl                  &control  = {});

  /// Name of the radial probe with ratio eps_rr / eps_zz = k.
  std::string
  radial_path_name(double k);

  /// A Drucker-Prager Cap row fitted to one branch.
  struct DpcFitRow
  {
    double relative_density;
    double cohesion;           ///< d [Pa]
    double friction_angle_deg; ///< beta [deg]
    double cap_eccentricity;   ///< R [-]
    double cap_pressure;       ///< p_b [Pa]
    double youngs_modulus;     ///< [Pa]
    double poisson_ratio;      ///< [-]
    /// Plastic density the cap through the compaction state belongs to:
    /// rho exp(-e), e = sum over the compaction rows of dp / K(rho) (the
    /// DPC's elastic volumetric strain along the path) [-].
    double plastic_density = 0.0;
    /// Cap pressure of the cap through the compaction state [Pa];
    /// cap_pressure is the table value at relative_density that gives it
    /// at plastic_density (cap_pressures_at_rows).
    double fitted_cap_pressure = 0.0;
  };

  /**
   * The density-dependent Drucker-Prager Cap fitted to a database, one row
   * per branch: the shear line through the two shear failures, the cap
   * through the loaded (compaction) state with the uniaxial flow normal
   * (cap_through_uniaxial_state), E and nu of the unloading tangent. The
   * DPC hardens its cap with the plastic density, which at the compaction
   * state lies below the density by the elastic volumetric strain; the
   * tabulated p_b are set so that the table gives each fitted cap at its
   * plastic density (DpcFitRow::plastic_density). A
   * branch whose shear line is not physical (tan beta <= 0, d < 0) is
   * fitted with d = max(d, 0) through the higher-pressure failure and the
   * flag set in the note.
   */
  std::vector<DpcFitRow>
  fit_drucker_prager_cap(const RveDatabase        &database,
                         std::vector<std::string> *notes = nullptr);
} // namespace compax::coupling
