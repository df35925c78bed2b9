#pragma once

#include "coupling/comparison_table.h"
#include "coupling/interior_comparison.h"
#include "coupling/rve_database_study.h"
#include "coupling/tablet_study.h"
#include "dem/die/die_study.h"
#include "dem/solver/consolidation.h"

#include <optional>
#include <string>
#include <vector>

namespace compax::coupling
{
  /// The particle bed as deposited in the die: what the tablet model is
  /// filled with, so that both start from the same powder column.
  struct DepositedFill
  {
    double relative_density = 0.0; ///< in-die [-]
    double height           = 0.0; ///< punch gap [m]
  };

  /// What the studies of one die and one particle material are compared
  /// at.
  struct ScaleComparisonSettings
  {
    double die_diameter  = 0.0; ///< [m]
    double final_density = 0.0; ///< in-die relative density [-]
    /// In-die densities at which the particle bed is unloaded, increasing,
    /// the last one final_density.
    std::vector<double> unloading_points;
    /// Further RVE database branches below the first unloading point.
    std::vector<double> loose_branches;
    /// Coulomb coefficient of the ejection pressure mu F_radial / A_punch
    /// (Gonzalez 2018 Sec. 5.4) [-].
    double wall_friction = 0.0;
    /// Samples of two studies this close in relative density are taken as
    /// at the same density (the RVE branches within a solver step of the
    /// requested density, the tablet ends within round-off of its target).
    double density_reach = 1e-3;
    /// Die stresses below this are not resolved [Pa] (the particle die's
    /// default resolution).
    double pressure_resolution
      = dem::ConsolidationOptions{}.pressure_resolution();
  };

  /// The results of the studies compared; a study that did not run or gave
  /// no result is left empty (its comparisons then have missing values).
  struct ScaleComparisonInputs
  {
    /// The direct particle simulation (the reference of most rows).
    const dem::DieStudyResult *die = nullptr;
    /// The RVE response database of the database-mode tablet and its fit.
    const RveDatabaseStudyResult *database = nullptr;
    /// The tablet on that database, and the FE2 tablet.
    const TabletStudyResult *tablet = nullptr;
    const TabletStudyResult *fe2    = nullptr;
  };

  /// What a scale comparison finds.
  struct ScaleComparisonResult
  {
    /// youngs_modulus, poisson_ratio, punch_pressure, ejection_pressure,
    /// fe2_vs_database, interior_sigma_zz, interior_lateral_ratio (in that
    /// order; see ScaleComparison::compare()).
    std::vector<ComparisonRow> rows;
    /// The die's interior beside the RVE; empty without a database.
    std::optional<std::vector<InteriorRow>> interior;
    /// Punch pressure against the rigid die's density along the FE2
    /// tablet's compaction (empty without one).
    DensitySeries fe2_compaction;
    /// Why the converged database-mode tablet has no ejection pressure
    /// (empty if it has one).
    std::string tablet_note;
  };

  /**
   * The scale comparison of issue #16: for one die and one particle
   * material, the direct particle simulation (dem::DieStudy) against the
   * RVE's homogenized moduli and the multiscale tablet (TabletStudy on the
   * RVE response database, and in FE2 mode), on the results in memory.
   * The caller runs the studies: the tablet is filled with deposited_fill()
   * of the die and its database branches at database_branches().
   */
  class ScaleComparison
  {
  public:
    /// Densest deposited bed an RVE starts from [-].
    static constexpr double densest_rve_start = 0.74;

    explicit ScaleComparison(ScaleComparisonSettings settings);

    /// The bed of the die's first row; throws std::invalid_argument if the
    /// die has no rows or the bed is too dense for an RVE to start from
    /// (densest_rve_start).
    static DepositedFill
    deposited_fill(const dem::DieStudyResult &die);

    /**
     * The densities at which the RVE database branches: the loose
     * branches above the fill and below the first unloading point, then
     * the unloading points above the fill (where an RVE can start). Throws
     * std::invalid_argument if fewer than two unloading points remain
     * (the database fits a density-dependent cap through them).
     */
    std::vector<double>
    database_branches(const DepositedFill &fill) const;

    /**
     * The comparison rows, each at the reference's samples with the
     * compared study interpolated in relative density (within
     * density_reach of its ends):
     * - youngs_modulus, poisson_ratio: the tablet's E and nu from the
     *   particle die's unloading branches (Gonzalez 2018 Sec. 5.7)
     *   against the RVE's homogenized moduli (the database's fit);
     * - punch_pressure: die against database-mode tablet along
     *   compaction, the tablet's density the rigid die's, rho_0 H_0 / H
     *   from the punch gap, as the particle die measures it;
     * - ejection_pressure: at the final density, mu times the residual
     *   die-wall force over the punch area (Sec. 5.4), of the die's last
     *   branch and of the converged tablet's end of unloading;
     * - fe2_vs_database: database-mode against FE2 tablet;
     * - interior_sigma_zz, interior_lateral_ratio: the die's interior
     *   against the RVE's compaction path (interior_comparison_rows()).
     */
    ScaleComparisonResult
    compare(const DepositedFill &fill, const ScaleComparisonInputs &in) const;

    const ScaleComparisonSettings &
    settings() const
    {
      return settings_;
    }

  private:
    ScaleComparisonSettings settings_;
  };

  /// Punch pressure against the rigid die's relative density, rho_0 H_0 / H
  /// with H the punch gap (the lower punch rests during compaction), over
  /// the compaction steps of a tablet filled with @p fill: the mesh's mean
  /// density also counts the penalty wall's give, which grows with the
  /// wall pressure, and the particle die measures the rigid die's.
  DensitySeries
  tablet_compaction(const TabletStudyResult &tablet, const DepositedFill &fill);
} // namespace compax::coupling
