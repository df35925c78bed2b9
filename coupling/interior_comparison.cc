#include "coupling/interior_comparison.h"

#include <cmath>

namespace compax::coupling
{
  std::vector<InteriorRow>
  compare_interior(const std::vector<dem::DieRecord> &die_rows,
                   const RveDatabase                 &database)
  {
    DensitySeries rve_zz, rve_xx;
    for (const DatabaseRow &r : database.rows)
      if (r.path == "compaction")
        {
          rve_zz.x.push_back(r.relative_density);
          rve_zz.y.push_back(r.stress[2]);
          rve_xx.x.push_back(r.relative_density);
          rve_xx.y.push_back(0.5 * (r.stress[0] + r.stress[1]));
        }

    std::vector<InteriorRow> rows;
    for (const dem::DieRecord &r : die_rows)
      if (r.stage == "compaction" && r.branch == 0
          && std::isfinite(r.rho_interior))
        rows.push_back({r.relative_density,
                        r.rho_interior,
                        r.sigma_zz_interior,
                        r.sigma_rr_interior,
                        interpolate(rve_zz, r.rho_interior),
                        interpolate(rve_xx, r.rho_interior)});
    return rows;
  }

  std::vector<ComparisonRow>
  interior_comparison_rows(const std::vector<InteriorRow> &rows,
                           const double                    resolution)
  {
    std::vector<ComparisonRow> out;
    const auto                 resolved = [&](const InteriorRow &r) {
      return std::abs(r.sigma_zz_interior) >= resolution
             && r.sigma_zz_interior != 0.0;
    };
    for (const InteriorRow &r : rows)
      if (resolved(r))
        out.push_back({"interior_sigma_zz",
                       r.relative_density_interior,
                       r.sigma_zz_interior,
                       r.sigma_zz_rve});
    for (const InteriorRow &r : rows)
      if (resolved(r) && r.sigma_rr_interior != 0.0)
        out.push_back({"interior_lateral_ratio",
                       r.relative_density_interior,
                       r.sigma_rr_interior / r.sigma_zz_interior,
                       r.sigma_xx_rve / r.sigma_zz_rve});
    return out;
  }
} // namespace compax::coupling
