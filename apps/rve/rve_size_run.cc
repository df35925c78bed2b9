#include "apps/rve/rve_size_run.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/rve/rve_pack.h"
#include "apps/rve/rve_run.h"
#include "dem/rve/rve_packing.h"
#include "dem/rve/rve_size_study.h"
#include "io/csv_writer.h"

#include <cmath>
#include <iostream>
#include <optional>

namespace compax::cli
{
  int
  run_rve_size_study(const coupling::RveStudy    &study,
                     const std::filesystem::path &folder)
  {
    const dem::RveSizeStudy sizes(study.model,
                                  {study.packing, study.cell_sizes, study});
    io::CsvWriter timing(folder / "timing.csv", {"particle_count", "seconds"});
    int           code = success;
    dem::PeriodicPackingSpec          spec;
    std::optional<coupling::RveStudy> one;
    std::optional<RvePathOutput>      output;
    dem::RveSizeObserver              observer;
    observer.packing = [&](std::size_t k, const dem::PeriodicPackingSpec &s) {
      spec = s;
      std::cout << "=== Cell size " << k + 1 << " of "
                << study.cell_sizes.size() << ": " << s.particle_count
                << " particles ===" << std::endl;
      print_packing(study, s);
    };
    observer.packed = [&](std::size_t, const dem::PeriodicBed &bed) {
      print_packed(study, spec, bed);
    };
    observer.path = [&](std::size_t) {
      const auto sub = folder / ("size-" + std::to_string(spec.particle_count));
      std::filesystem::create_directories(sub);
      one.emplace(study);
      one->packing = spec;
      output.emplace(*one, sub);
      return output->observer();
    };
    observer.done = [&](std::size_t,
                        const dem::RveSizeCell  &cell,
                        const dem::RvePathStudy &path) {
      const RveOutcome o = output->finish(cell.path, path);
      code               = o.code;
      timing << static_cast<long long>(spec.particle_count) << o.timings.total;
      timing.end_row();
    };
    dem::RveSizeResult result;
    try
      {
        result = sizes.run(observer);
      }
    catch (const dem::DepositDensityError &e)
      {
        coupling::reject_deposit_density(spec, e.deposit_density);
      }

    const auto              &quantities = dem::rve_size_quantities();
    std::vector<std::string> columns{"particle_count",
                                     "seed",
                                     "cell_edge_over_mean_diameter"};
    columns.insert(columns.end(), quantities.begin(), quantities.end());
    {
      io::CsvWriter csv(folder / "rve_size_study.csv", columns);
      for (const dem::RveSizeCell &cell : result.cells)
        {
          csv << static_cast<long long>(cell.packing.particle_count)
              << static_cast<long long>(cell.packing.seed)
              << cell.edge_over_diameter;
          for (const double v : cell.quantities)
            if (std::isnan(v))
              csv.empty();
            else
              csv << v;
          csv.end_row();
        }
    }
    io::CsvWriter spread(folder / "rve_size_spread.csv",
                         {"quantity", "min", "max", "mean", "spread"});
    std::cout << "Spread between cell sizes, (max - min)/|mean|:" << std::endl;
    for (const dem::RveSizeSpread &s : result.spread)
      {
        spread << s.quantity;
        if (s.count == 0)
          {
            spread.empty().empty().empty().empty();
            spread.end_row();
            continue;
          }
        spread << s.min << s.max << s.mean;
        if (std::isnan(s.spread))
          spread.empty();
        else
          spread << s.spread;
        spread.end_row();
        std::cout << "  " << s.quantity << ": " << s.spread << std::endl;
      }
    return code;
  }
} // namespace compax::cli
