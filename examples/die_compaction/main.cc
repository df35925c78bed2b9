// Die compaction of a few hundred bonded elasto-plastic spheres with the
// installed compax library (Gonzalez 2018, Sec. 5): ballistic deposition
// into a rigid cylindrical die, compaction by the upper punch through static
// equilibria, one unloading branch and ejection. Prints punch pressure
// against in-die relative density and the branch's elastic recovery, and
// exits non-zero unless the results are physical.

#include <dem/die/die_compaction.h>
#include <dem/die/die_setup.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <utility>

namespace dem = compax::dem;

int
main()
{
  // Material 1 of Gonzalez 2018, Table 1: monodisperse spheres.
  const dem::ElastoplasticMaterial material{/*E*/ 5e9,
                                            /*nu*/ 0.25,
                                            /*kappa*/ 150e6,
                                            /*m*/ 2.0};
  const dem::ContactModel          model(material, /*K_Ic [Pa m^1/2]*/ 1.26e6);

  dem::DepositionParameters deposition;
  deposition.n_particles         = 300;
  deposition.die_diameter        = 4e-3;
  deposition.sizes.median_radius = 220e-6;
  deposition.seed                = 1;
  dem::Bed bed                   = dem::fill_die(deposition);
  std::printf("%zu particles deposited in a %.1f mm die: relative density "
              "%.3f\n",
              deposition.n_particles,
              deposition.die_diameter * 1e3,
              bed.relative_density());

  const double     rho_max = 0.80;
  dem::DieProtocol protocol;
  protocol.compaction_targets
    = dem::density_targets(bed.relative_density(), rho_max, 16);
  protocol.unloading_points = {rho_max};

  dem::DieCompaction die(std::move(bed), model, protocol);
  try
    {
      die.run();
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "die compaction failed: %s\n", e.what());
      return 1;
    }

  int        failures = 0;
  const auto check    = [&failures](bool ok, const char *what) {
    if (!ok)
      {
        std::fprintf(stderr, "FAILED: %s\n", what);
        ++failures;
      }
  };

  std::printf("\n%-11s %8s %10s %10s %10s\n",
              "stage",
              "rho [-]",
              "p_up [MPa]",
              "p_lo [MPa]",
              "wall [MPa]");
  double last_pressure = -1.0, worst_imbalance = 0.0;
  for (const dem::DieRecord &r : die.records())
    {
      if (r.stage == "ejection")
        continue;
      std::printf("%-11s %8.4f %10.3f %10.3f %10.3f\n",
                  r.stage.c_str(),
                  r.relative_density,
                  r.upper_punch_pressure / 1e6,
                  r.lower_punch_pressure / 1e6,
                  r.die_wall_pressure / 1e6);
      // The die wall is frictionless, so it carries no axial load: the
      // punches balance up to the particles' residual forces, whose sum is
      // at most N times the largest one (relative residual x mean force).
      const double imbalance
        = std::abs(r.upper_punch_force - r.lower_punch_force);
      const double bound
        = double(deposition.n_particles) * r.residual * r.mean_contact_force
          + 1e-12 * std::abs(r.upper_punch_force);
      if (!(r.stage == "compaction" && r.step == 0)) // the loose deposit
        {
          check(imbalance <= bound, "upper and lower punch forces balance");
          worst_imbalance = std::max(worst_imbalance, imbalance / bound);
        }
      // Compaction of a jammed bed: the punch pressure rises with density
      // (a loose state's balanced forces are below what the study resolves).
      if (r.stage == "compaction"
          && r.upper_punch_pressure
               > protocol.consolidation.pressure_resolution())
        {
          check(r.upper_punch_pressure > last_pressure,
                "punch pressure increases with density");
          last_pressure = r.upper_punch_pressure;
        }
    }

  std::printf("punch forces balance on every row: largest |F_upper - "
              "F_lower| is %.2g of the solver's residual bound\n",
              worst_imbalance);

  check(die.branches().size() == 1, "one unloading branch");
  if (die.branches().size() == 1)
    {
      const dem::BranchSummary &b = die.branches().front();
      std::printf("\nunloading branch from rho_max = %.4f: rho_min = %.4f, "
                  "elastic recovery eps_rho = %.2f %%, eps_H = %.2f %%, "
                  "residual radial pressure %.3f MPa, ejection pressure "
                  "(mu = 1) %.3f MPa, tablet density "
                  "%.4f\n",
                  b.rho_max_in_die,
                  b.rho_min_in_die,
                  100 * b.elastic_recovery_rho,
                  100 * b.elastic_recovery_H,
                  b.residual_radial_pressure / 1e6,
                  b.ejection_pressure / 1e6,
                  b.rho_tablet);
      check(std::abs(b.rho_max_in_die - rho_max) < 1e-9,
            "the branch starts at rho_max");
      check(b.max_punch_pressure > 0.0, "the compact carries load");
      // Unloading releases stored elastic energy: the compact expands, by
      // a few percent for Material 1 (Gonzalez 2018, Fig. 9).
      check(b.rho_min_in_die < b.rho_max_in_die, "unloading lowers density");
      check(b.elastic_recovery_rho > 0.0 && b.elastic_recovery_rho < 0.2,
            "elastic recovery between 0 and 20 %");
      check(b.residual_radial_pressure >= 0.0,
            "the die wall still presses the unloaded compact");
    }

  if (failures > 0)
    {
      std::fprintf(stderr, "%d check(s) failed\n", failures);
      return 1;
    }
  std::printf("all checks passed\n");
  return 0;
}
