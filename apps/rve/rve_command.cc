#include "apps/rve/rve_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/csv_writer.h"
#include "apps/rve/rve_parameters.h"
#include "apps/rve/rve_run.h"
#include "dem/rve/rve_packing.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace compax::cli
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The packing of one run, with a line on screen.
    dem::PeriodicBed
    pack(const RveStudy &study, const dem::PeriodicPackingSpec &spec)
    {
      const bool deposited = spec.protocol == dem::PackingProtocol::deposited;
      std::cout << "Packing " << spec.particle_count
                << " spheres in a periodic cell (" << study.size_description
                << ", seed " << spec.seed << ", "
                << (deposited ? "deposited, compacted uniaxially"
                              : "compressed gas")
                << ") to a relative density of " << spec.relative_density
                << " ..." << std::endl;
      // Elastic spheres are packed with the bonded law's elastic branch,
      // virgin: a deposit is compacted with frozen histories.
      dem::RveLoadingOptions loading = study.loading;
      if (study.elastic)
        loading.consolidation = dem::RveConsolidation::frozen_history;
      dem::PeriodicBed bed;
      try
        {
          bed = dem::make_rve_packing(spec, study.model, loading);
        }
      catch (const dem::DepositDensityError &e)
        {
          reject_deposit_density(spec, e.deposit_density);
        }
      if (deposited)
        std::cout << "  deposit compacted on the "
                  << (loading.consolidation == dem::RveConsolidation::none
                        ? "bonded path"
                        : "frozen-history path")
                  << std::endl;
      std::cout << "  cell edge " << bed.cell.lattice()(0, 0) << " m = "
                << bed.cell.lattice()(0, 0)
                     / (2.0 * bed.particles.mean_radius())
                << " mean diameters" << std::endl;
      return bed;
    }

    /// The last row of a table whose column `stage` equals `stage` (or any
    /// stage if negative), NaN row if none.
    std::vector<double>
    last_row(const std::vector<std::vector<double>> &rows,
             std::size_t                             stage_column,
             double                                  stage,
             std::size_t                             width)
    {
      for (auto it = rows.rbegin(); it != rows.rend(); ++it)
        if (stage < 0 || (*it)[stage_column] == stage)
          return *it;
      return std::vector<double>(width, nan);
    }

    /**
     * RVE-size study (Giannis 2021 Sec. 4.1): the same path for every cell
     * size, in size-<N>/; per size the stress at the end of loading and
     * the moduli there and at the end; the spread (max - min)/mean between
     * the sizes.
     */
    int
    run_size_study(const RveStudy &study, const std::filesystem::path &folder)
    {
      const std::vector<std::string> quantities{"relative_density_loaded",
                                                "sigma_xx_loaded",
                                                "sigma_yy_loaded",
                                                "sigma_zz_loaded",
                                                "mean_pressure_loaded",
                                                "E_loaded",
                                                "nu_loaded",
                                                "E_end",
                                                "nu_end"};
      std::vector<std::string>       columns{"particle_count",
                                       "seed",
                                       "cell_edge_over_mean_diameter"};
      columns.insert(columns.end(), quantities.begin(), quantities.end());
      std::vector<std::vector<double>> table;
      CsvWriter timing(folder / "timing.csv", {"particle_count", "seconds"});
      int       code = success;
      for (std::size_t k = 0; k < study.cell_sizes.size() && code == success;
           ++k)
        {
          dem::PeriodicPackingSpec spec = study.packing;
          spec.particle_count           = study.cell_sizes[k];
          spec.seed                     = study.packing.seed + k;
          const auto sub
            = folder / ("size-" + std::to_string(spec.particle_count));
          std::filesystem::create_directories(sub);
          std::cout << "=== Cell size " << k + 1 << " of "
                    << study.cell_sizes.size() << ": " << spec.particle_count
                    << " particles ===" << std::endl;
          dem::PeriodicBed bed  = pack(study, spec);
          const double     edge = std::cbrt(bed.cell.volume())
                              / (2.0 * bed.particles.mean_radius());
          RveStudy one       = study;
          one.packing        = spec;
          const RveOutcome o = run_rve_path(one, std::move(bed), sub);
          code               = o.code;
          const auto &rows   = o.progress.rows;
          const auto &mod    = o.progress.moduli;
          const auto  loaded
            = last_row(rows, rve_column("stage"), 0.0, rve_columns().size());
          const auto m_loaded = last_row(mod,
                                         moduli_column("stage"),
                                         0.0,
                                         moduli_columns().size());
          const auto m_end    = last_row(mod,
                                      moduli_column("stage"),
                                      -1.0,
                                      moduli_columns().size());
          table.push_back({double(spec.particle_count),
                           double(spec.seed),
                           edge,
                           loaded[rve_column("relative_density")],
                           loaded[rve_column("sigma_xx")],
                           loaded[rve_column("sigma_yy")],
                           loaded[rve_column("sigma_zz")],
                           loaded[rve_column("mean_pressure")],
                           m_loaded[moduli_column("E")],
                           m_loaded[moduli_column("nu")],
                           m_end[moduli_column("E")],
                           m_end[moduli_column("nu")]});
          timing << static_cast<long long>(spec.particle_count)
                 << o.timings.total;
          timing.end_row();
        }

      {
        CsvWriter csv(folder / "rve_size_study.csv", columns);
        for (const auto &row : table)
          {
            for (std::size_t c = 0; c < row.size(); ++c)
              if (std::isnan(row[c]))
                csv.empty();
              else if (c < 2)
                csv << static_cast<long long>(row[c]);
              else
                csv << row[c];
            csv.end_row();
          }
      }
      CsvWriter spread(folder / "rve_size_spread.csv",
                       {"quantity", "min", "max", "mean", "spread"});
      std::cout << "Spread between cell sizes, (max - min)/|mean|:"
                << std::endl;
      for (std::size_t q = 0; q < quantities.size(); ++q)
        {
          double lo = std::numeric_limits<double>::infinity(), hi = -lo,
                 sum = 0.0;
          int n      = 0;
          for (const auto &row : table)
            if (const double v = row[3 + q]; !std::isnan(v))
              {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
                sum += v;
                ++n;
              }
          spread << quantities[q];
          if (n == 0)
            {
              spread.empty().empty().empty().empty();
              spread.end_row();
              continue;
            }
          const double mean = sum / n;
          const double s    = mean != 0.0 ? (hi - lo) / std::abs(mean) : nan;
          spread << lo << hi << mean;
          if (std::isnan(s))
            spread.empty();
          else
            spread << s;
          spread.end_row();
          std::cout << "  " << quantities[q] << ": " << s << std::endl;
        }
      return code;
    }

    class RveCommand : public Command
    {
    public:
      std::string
      name() const override
      {
        return "rve";
      }

      std::string
      summary() const override
      {
        return "periodic RVE along a strain path: stress, tangent, moduli";
      }

      std::string
      description() const override
      {
        return "Packs bonded elasto-plastic spheres in a fully periodic "
               "cell (by default a cell cut from a ballistic deposit, "
               "compacted uniaxially on the bonded path to the initial "
               "density; or compression of a loose gas, virgin histories) "
               "and drives the cell along a macroscopic strain path "
               "(uniaxial strain, hydrostatic, or increments from a CSV), "
               "each step a static equilibrium of the fluctuations by "
               "trust-region Newton with the internal variables updated on "
               "converged steps (Gonzalez 2018 Eq. 13), then optionally "
               "unloads along the same path. Homogenized Cauchy stress by "
               "the Love-Weber formula; consistent tangent by static "
               "condensation (and the affine tangent); elastic moduli from "
               "the unloading-branch tangent.\n\nWrites rve.csv (per step: "
               "logarithmic strain of F, Love-Weber stress in Pa, tension "
               "positive, relative density, coordination number, bonding "
               "surface, bonds, solver iterations; the time of each step "
               "and tangent goes to timing.csv), moduli.csv (isotropic E "
               "and nu and the transversely isotropic constants of the "
               "unloading-branch condensed tangent; C11 C33 C12 C13 C44 of "
               "the condensed and affine tangents; tangent_fd_error where "
               "checked against finite differences), stress_strain.png, "
               "moduli.png, snapshots/*.vtu with snapshots.pvd, and "
               "checkpoints/rve.h5 if asked. With Size study/Cell sizes: one "
               "run per cell in size-<N>/, rve_size_study.csv and "
               "rve_size_spread.csv (Giannis 2021 Sec. 4.1). Contact/Contact "
               "law = elastic packs elastic frictionless spheres instead (no "
               "bonding, no tangents: moduli.csv stays empty), and "
               "Contact/Formulation = nonlocal then selects the nonlocal "
               "contact formulation of Gonzalez & Cuitino 2012 in place of "
               "Hertz.\n\nBuilt-in "
               "default: 200 spheres of Material 1 of Gonzalez 2018 Table 1 "
               "(E = 5 GPa, nu = 0.25, kappa = 150 MPa, R = 220 um, K_Ic = "
               "1.26 MPa m^1/2), uniaxial strain from a relative density of "
               "0.55 to 0.80 in 25 steps, then unloading until the axial "
               "stress vanishes.";
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        declare_rve_parameters(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        const RveStudy study = get_rve_study(prm);
        if (!study.resume_from.empty())
          {
            dem::PeriodicBed bed;
            read_rve_checkpoint(study.resume_from, study, bed);
          }
        else if (study.cell_sizes.empty())
          check_deposit_density(study.packing);
        else
          for (std::size_t k = 0; k < study.cell_sizes.size(); ++k)
            {
              dem::PeriodicPackingSpec spec = study.packing;
              spec.particle_count           = study.cell_sizes[k];
              spec.seed                     = study.packing.seed + k;
              check_deposit_density(spec);
            }
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const RveStudy study = get_rve_study(prm);
        if (study.elastic)
          std::cout << "Elastic frictionless spheres, "
                    << (study.elastic->nonlocal
                          ? "nonlocal contact formulation (Gonzalez & "
                            "Cuitino 2012)"
                          : "Hertz contacts")
                    << std::endl;
        if (!study.cell_sizes.empty())
          return run_size_study(study, folder);
        if (!study.resume_from.empty())
          {
            dem::PeriodicBed  bed;
            const RveProgress progress
              = read_rve_checkpoint(study.resume_from, study, bed);
            return run_rve_path(study, std::move(bed), folder, &progress).code;
          }
        return run_rve_path(study, pack(study, study.packing), folder).code;
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_rve_command()
  {
    return std::make_unique<RveCommand>();
  }
} // namespace compax::cli
