#include "apps/die/jamming_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "coupling/parameters/die_parameters.h"
#include "dem/die/die_setup.h"
#include "dem/die/jamming_study.h"

#include <fstream>
#include <iomanip>
#include <iostream>

namespace compax::cli
{
  namespace
  {
    /// The cases of the study, read from subsection Jamming.
    struct JammingStudyInput
    {
      std::string                   material;
      std::vector<dem::JammingCase> cases;
    };

    JammingStudyInput
    read_jamming(dealii::ParameterHandler &prm, const coupling::DieInput &die)
    {
      JammingStudyInput in;
      prm.enter_subsection("Jamming");
      in.material                 = prm.get("Material label");
      const bool        without   = prm.get_bool("Compare without bonds");
      const std::string protocols = prm.get("Protocols");
      prm.leave_subsection();
      // A registered law forms no bridges: its cases carry K_Ic = 0.
      std::vector<double> toughness{
        die.model.registered_law() ? 0.0 : die.model.fracture_toughness(0, 0)};
      if (without && toughness[0] > 0.0)
        toughness.push_back(0.0);
      for (const auto &protocol :
           dealii::Utilities::split_string_list(protocols, ','))
        for (const double K : toughness)
          in.cases.push_back({K, protocol == "frozen-history"});
      if (in.cases.empty())
        reject_entry("Jamming/Protocols", "''", "give one or both protocols");
      if (die.study.protocol.elastic)
        reject_entry("Contact/Contact law",
                     "elastic",
                     "the jamming study compares bonded beds; use bonded");
      return in;
    }

    /// jamming_path.csv: the compaction path of every case.
    void
    write_paths(const std::filesystem::path           &file,
                const std::vector<dem::JammingResult> &results)
    {
      std::ofstream out(file);
      out.precision(10);
      out << "fracture_toughness,protocol,step,relative_density,"
             "upper_punch_pressure,coordination_number,bonds,"
             "bonding_surface,relaxed,residual\n";
      for (const auto &r : results)
        for (const auto &d : r.records)
          out << r.study_case.fracture_toughness << ','
              << r.study_case.protocol_name() << ',' << d.step << ','
              << d.relative_density << ',' << d.upper_punch_pressure << ','
              << d.coordination_number << ',' << d.bonds << ','
              << d.bonding_surface << ',' << d.relaxed << ',' << d.residual
              << '\n';
    }

    class JammingCommand : public Command
    {
    public:
      JammingCommand()
          : Command(
            {"jamming",
             "where a deposit jams in the die: bonded path against "
             "frozen-history consolidation, K_Ic > 0 against K_Ic = 0 "
             "(Gonzalez 2018, Sec. 5.1, Eq. 14)",
             "Deposits the bed of the die parameters (Material, Bonding, "
             "Packing, Solver; see `compax die --help`) once and compacts "
             "it without unloading to Protocol/Final relative density in "
             "Protocol/Compaction steps, once per case: each protocol of "
             "Jamming/Protocols (bonded-path: Eq. 13 on every converged "
             "state from the deposit on; frozen-history: relaxation at "
             "virgin internal variables until the punch carries 0.5 MPa), "
             "with the Bonding/Fracture toughness and, if Jamming/Compare "
             "without bonds, with K_Ic = 0. Eq. (14) Z = Z_c + Z_0 (rho - "
             "rho_c_Z)^theta is fitted to the compaction states whose "
             "upper punch carries more than the pressure resolution "
             "(5 kPa).\n\nWrites jamming.csv (material, fracture_toughness "
             "[Pa m^1/2], protocol, rho_c_Z, Z_c, theta; empty fit cells "
             "where Eq. 14 could not be fitted; rho_jammed, Z_jammed: the "
             "first state whose punches carried 0.5 MPa, a measure that "
             "needs no fit; rho_c_Z_interior, Z_c_interior, "
             "theta_interior: Eq. 14 fitted to the die's interior, the "
             "region farther than two diameters from every wall, with "
             "its own solid fraction, coordination number and axial "
             "stress; contact_law: bonded-elastoplastic or the "
             "registered Contact/Contact law), jamming_path.csv (every "
             "case's compaction path: density, punch pressure [Pa], "
             "coordination number, bonds, bonding surface [m^2], whether "
             "the state is an unjammed relaxation, residual) and "
             "timing.csv (wall seconds per case). Exit code 3 if a case "
             "stopped early (its rows so far are kept and fitted).\n\n"
             "Built-in default: the die defaults (400 particles of "
             "Material 1), all four cases. Shipped: "
             "apps/parameters/jamming_material{1,2}_6512.prm."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        coupling::declare_die_parameters(prm);
        prm.enter_subsection("Jamming");
        prm.declare_entry("Material label",
                          "material1",
                          dealii::Patterns::Anything(),
                          "Name written in the material column of "
                          "jamming.csv. Unit: -.");
        prm.declare_entry("Protocols",
                          "bonded-path, frozen-history",
                          dealii::Patterns::MultipleSelection(
                            "bonded-path|frozen-history"),
                          "The loose-regime protocols to compare. Unit: -.");
        prm.declare_entry("Compare without bonds",
                          "true",
                          dealii::Patterns::Bool(),
                          "Also run every protocol with K_Ic = 0 (no solid "
                          "bridges), on the same deposit. A registered "
                          "Contact law forms no bridges: its cases run once, "
                          "with K_Ic = 0 in jamming.csv. Unit: -.");
        prm.leave_subsection();
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        read_jamming(prm, coupling::get_die_input(prm));
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        coupling::DieInput      die   = coupling::get_die_input(prm);
        dem::DieStudyOptions   &study = die.study;
        const JammingStudyInput input = read_jamming(prm, die);
        std::cout << "Packing " << study.deposition.n_particles
                  << " particles by ballistic deposition ..." << std::endl;
        const dem::Bed deposit = dem::fill_die(study.deposition);
        coupling::set_compaction_targets(study, deposit.relative_density());

        std::vector<dem::JammingResult> results;
        bool                            failed = false;
        for (const dem::JammingCase &c : input.cases)
          {
            std::cout << std::setprecision(6)
                      << "Case K_Ic = " << c.fracture_toughness << " Pa m^1/2, "
                      << c.protocol_name() << std::endl;
            results.push_back(dem::run_jamming_case(deposit,
                                                    die.model,
                                                    study.protocol,
                                                    study.equilibrium,
                                                    c,
                                                    &std::cout));
            const dem::JammingResult &r = results.back();
            if (!r.failure.empty())
              {
                failed = true;
                std::cout << "  stopped early: " << r.failure << std::endl;
              }
            std::cout << std::setprecision(4) << "  punch at the jamming "
                      << "pressure from rho " << r.jamming_density << " (Z "
                      << r.jamming_coordination << "), " << r.seconds << " s"
                      << std::endl;
            if (r.fit)
              std::cout << "  Eq. 14: rho_c_Z " << r.fit->rho_c << "  Z_c "
                        << r.fit->Z_c << "  theta " << r.fit->theta
                        << std::endl;
          }
        std::ofstream csv(folder / "jamming.csv");
        dem::write_jamming_csv(csv,
                               input.material,
                               die.model.law_name(),
                               results);
        write_paths(folder / "jamming_path.csv", results);
        std::ofstream timing(folder / "timing.csv");
        timing << "fracture_toughness,protocol,wall_seconds\n";
        for (const auto &r : results)
          timing << r.study_case.fracture_toughness << ','
                 << r.study_case.protocol_name() << ',' << r.seconds << '\n';
        return failed ? ExitCode::not_converged : ExitCode::success;
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_jamming_command()
  {
    return std::make_unique<JammingCommand>();
  }
} // namespace compax::cli
