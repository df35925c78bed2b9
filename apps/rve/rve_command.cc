#include "apps/rve/rve_command.h"

#include "apps/cli/parameters.h"
#include "apps/rve/rve_pack.h"
#include "apps/rve/rve_run.h"
#include "apps/rve/rve_size_run.h"
#include "coupling/parameters/rve_parameters.h"
#include "dem/rve/rve_size_study.h"

#include <iostream>

namespace compax::cli
{
  namespace
  {
    class RveCommand : public Command
    {
    public:
      RveCommand()
          : Command(
            {"rve",
             "periodic RVE along a strain path: stress, tangent, moduli",
             "Packs bonded elasto-plastic spheres in a fully periodic "
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
             "moduli.png, jamming.csv (uniaxial compaction of the bonded "
             "law: Gonzalez 2018 Eq. 14 fitted to the loading states whose "
             "-sigma_zz exceeds the die's pressure resolution, 1e-2 of the "
             "jamming pressure, as the die fits it: rho_c_Z, Z_c, Z_0, "
             "theta, rms, jammed_states; empty cells when it cannot be "
             "fitted), snapshots/*.vtu with snapshots.pvd, and "
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
             "stress vanishes."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        coupling::declare_rve_parameters(prm);
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        const coupling::RveStudy study = coupling::get_rve_study(prm);
        if (!study.resume_from.empty())
          {
            dem::PeriodicBed bed;
            read_rve_checkpoint(study.resume_from, study, bed);
          }
        else if (study.cell_sizes.empty())
          coupling::check_deposit_density(study.packing);
        else
          {
            const dem::RveSizeStudy sizes(
              study.model, {study.packing, study.cell_sizes, {}});
            for (std::size_t k = 0; k < study.cell_sizes.size(); ++k)
              coupling::check_deposit_density(sizes.packing(k));
          }
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const coupling::RveStudy study = coupling::get_rve_study(prm);
        if (study.elastic)
          std::cout << "Elastic frictionless spheres, "
                    << (study.elastic->nonlocal
                          ? "nonlocal contact formulation (Gonzalez & "
                            "Cuitino 2012)"
                          : "Hertz contacts")
                    << std::endl;
        if (!study.cell_sizes.empty())
          return run_rve_size_study(study, folder);
        if (!study.resume_from.empty())
          {
            dem::PeriodicBed  bed;
            const RveProgress progress
              = read_rve_checkpoint(study.resume_from, study, bed);
            return run_rve_path(study, std::move(bed), folder, &progress).code;
          }
        return run_rve_path(study, pack_rve(study, study.packing), folder).code;
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_rve_command()
  {
    return std::make_unique<RveCommand>();
  }
} // namespace compax::cli
