#pragma once

#include "coupling/dpc_calibration.h"
#include "coupling/elastic_moduli.h"
#include "dem/rve/homogenization.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"

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
  };

  /// One equilibrated state along a database path.
  struct DatabaseRow
  {
    /// -1 on the compaction path, else the branch index.
    int         branch;
    std::string path; ///< compaction, unloading, shear, confined_shear
    double      relative_density;
    /// Engineering shear strain of a probe (0 elsewhere) [-].
    double        shear_strain;
    dem::Vector6d stress; ///< Love-Weber Cauchy stress, Voigt [Pa]
  };

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
   * the stress where the compact fails in shear. Progress lines go to
   * `progress` (may be empty).
   */
  RveDatabase
  build_rve_database(const DatabaseSpec                     &spec,
                     const dem::ContactModel                &model,
                     const std::function<void(std::string)> &progress = {});

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
  };

  /**
   * The density-dependent Drucker-Prager Cap fitted to a database, one row
   * per branch: the shear line through the two shear failures, the cap
   * through the loaded (compaction) state with the uniaxial flow normal
   * (cap_through_uniaxial_state), E and nu of the unloading tangent. A
   * branch whose shear line is not physical (tan beta <= 0, d < 0) is
   * fitted with d = max(d, 0) through the higher-pressure failure and the
   * flag set in the note.
   */
  std::vector<DpcFitRow>
  fit_drucker_prager_cap(const RveDatabase        &database,
                         std::vector<std::string> *notes = nullptr);
} // namespace compax::coupling
