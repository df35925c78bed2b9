#pragma once

#include "coupling/comparison_table.h"
#include "coupling/rve_database.h"
#include "dem/die/die_compaction.h"

#include <vector>

namespace compax::coupling
{
  /**
   * The die's interior against the RVE (issue #15, item 4): at each
   * compaction state of the particle die, the solid fraction and stress of
   * its interior (DieRecord::rho_interior, sigma_zz_interior,
   * sigma_rr_interior, the region farther than two diameters from every
   * wall, measure_interior()) beside the RVE's stress along its uniaxial
   * compaction path (database rows of path "compaction") interpolated at the
   * interior's own solid fraction. The wall layer of a die is looser than
   * its interior, so the interior, not the die average, is what a periodic
   * cell represents.
   */
  struct InteriorRow
  {
    double relative_density_die;      ///< die average [-]
    double relative_density_interior; ///< [-]
    double sigma_zz_interior;         ///< [Pa], tension positive
    double sigma_rr_interior;         ///< [Pa]
    /// RVE at relative_density_interior; NaN outside its compaction path.
    double sigma_zz_rve; ///< [Pa]
    /// Lateral stress of the RVE, (sigma_xx + sigma_yy) / 2 (equal up to
    /// the cell's fluctuations under uniaxial strain) [Pa].
    double sigma_xx_rve;
  };

  /// One row per state of the die's compaction path (compaction rows of
  /// branch 0 with an interior) among @p die_rows, beside the RVE of
  /// @p database.
  std::vector<InteriorRow>
  compare_interior(const std::vector<dem::DieRecord> &die_rows,
                   const RveDatabase                 &database);

  /// Comparison rows of the interior: interior_sigma_zz
  /// (reference the die interior's sigma_zz, value the RVE's) and
  /// interior_lateral_ratio (sigma_rr / sigma_zz of the interior against
  /// sigma_xx / sigma_zz of the RVE), both at the interior's density and
  /// where the interior's |sigma_zz| reaches @p resolution [Pa].
  std::vector<ComparisonRow>
  interior_comparison_rows(const std::vector<InteriorRow> &rows,
                           double                          resolution);
} // namespace compax::coupling
