#include "apps/compare/interior_comparison.h"

#include "apps/common/csv_writer.h"

#include <cmath>

namespace compax::cli
{
  std::vector<InteriorRow>
  compare_interior(const CsvTable &die_csv, const CsvTable &database_csv)
  {
    DensitySeries rve_zz, rve_xx;
    {
      const auto &path = database_csv.text("path");
      const auto  rho  = database_csv.numbers("relative_density");
      const auto  xx   = database_csv.numbers("sigma_xx");
      const auto  yy   = database_csv.numbers("sigma_yy");
      const auto  zz   = database_csv.numbers("sigma_zz");
      for (std::size_t k = 0; k < database_csv.rows(); ++k)
        if (path[k] == "compaction")
          {
            rve_zz.x.push_back(rho[k]);
            rve_zz.y.push_back(zz[k]);
            rve_xx.x.push_back(rho[k]);
            rve_xx.y.push_back(0.5 * (xx[k] + yy[k]));
          }
    }

    std::vector<InteriorRow> rows;
    const auto              &stage  = die_csv.text("stage");
    const auto               branch = die_csv.numbers("branch");
    const auto               rho    = die_csv.numbers("relative_density");
    const auto               rho_i  = die_csv.numbers("rho_interior");
    const auto               zz     = die_csv.numbers("sigma_zz_interior");
    const auto               rr     = die_csv.numbers("sigma_rr_interior");
    for (std::size_t k = 0; k < die_csv.rows(); ++k)
      if (stage[k] == "compaction" && branch[k] == 0.0
          && std::isfinite(rho_i[k]))
        rows.push_back({rho[k],
                        rho_i[k],
                        zz[k],
                        rr[k],
                        interpolate(rve_zz, rho_i[k]),
                        interpolate(rve_xx, rho_i[k])});
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

  void
  write_interior_csv(const std::filesystem::path    &file,
                     const std::vector<InteriorRow> &rows)
  {
    CsvWriter csv(file,
                  {"relative_density_die",
                   "relative_density_interior",
                   "sigma_zz_interior",
                   "sigma_rr_interior",
                   "sigma_zz_rve",
                   "sigma_xx_rve"});
    for (const InteriorRow &r : rows)
      {
        for (const double v : {r.relative_density_die,
                               r.relative_density_interior,
                               r.sigma_zz_interior,
                               r.sigma_rr_interior,
                               r.sigma_zz_rve,
                               r.sigma_xx_rve})
          if (std::isfinite(v))
            csv << v;
          else
            csv.empty();
        csv.end_row();
      }
    csv.close();
  }
} // namespace compax::cli
