#include "apps/compare/compare_studies.h"

#include "apps/cli/input_error.h"

#include <deal.II/base/exceptions.h>

#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    namespace fs = std::filesystem;

    /// Sets "A/B/name" = value in prm; a value the entry's pattern rejects
    /// is an InputError naming @p study.
    void
    set_entry(dealii::ParameterHandler &prm,
              const std::string        &path,
              const std::string        &value,
              const std::string        &study)
    {
      std::vector<std::string> parts;
      {
        std::stringstream s(path);
        for (std::string p; std::getline(s, p, '/');)
          parts.push_back(p);
      }
      for (std::size_t k = 0; k + 1 < parts.size(); ++k)
        prm.enter_subsection(parts[k]);
      try
        {
          prm.set(parts.back(), value);
        }
      catch (const dealii::ExceptionBase &)
        {
          for (std::size_t k = 0; k + 1 < parts.size(); ++k)
            prm.leave_subsection();
          throw InputError("the " + study + " study does not accept '" + path
                           + "' = " + value);
        }
      for (std::size_t k = 0; k + 1 < parts.size(); ++k)
        prm.leave_subsection();
    }

    /// The compare entry a sub-study entry was set from, for messages:
    /// "Packing/Die diameter" of compax die is "Die/Die diameter" here.
    std::string
    compare_entry(const std::string &entry)
    {
      static const std::vector<std::pair<std::string, std::string>> prefixes
        = {{"Packing/", "Die/"},
           {"Protocol/", "Die/"},
           {"Multiscale/Material/", "Material/"},
           {"Multiscale/Bonding/", "Bonding/"}};
      if (entry.rfind("Material/", 0) == 0 || entry.rfind("Bonding/", 0) == 0)
        return entry;
      for (const auto &[from, to] : prefixes)
        if (entry.rfind(from, 0) == 0)
          return to + entry.substr(from.size());
      return "";
    }
  } // namespace

  std::string
  number(const double value)
  {
    std::ostringstream s;
    s << std::setprecision(15) << value;
    return s.str();
  }

  void
  prepare(const Command            &command,
          dealii::ParameterHandler &prm,
          const Settings           &settings,
          const std::string        &study)
  {
    command.declare_parameters(prm);
    for (const auto &[path, value] : settings)
      set_entry(prm, path, value, study);
    try
      {
        command.check_parameters(prm);
      }
    catch (const InputError &e)
      {
        // A rejected entry that compare set from one of its own is named
        // as the user wrote it.
        const std::string message = e.what();
        for (const auto &[path, value] : settings)
          {
            const std::string quoted = "entry '" + path + "'";
            const std::string own    = compare_entry(path);
            if (!own.empty() && message.rfind(quoted, 0) == 0)
              throw InputError("entry '" + own + "'"
                               + message.substr(quoted.size()) + " (in the "
                               + study + " study)");
          }
        throw InputError("in the " + study
                         + " study compare sets up: " + message);
      }
  }

  void
  run_study(
    const Command     &command,
    const Settings    &settings,
    const fs::path    &parent,
    const std::string &study,
    StudyStatus       &status,
    const std::function<int(dealii::ParameterHandler &, const fs::path &)> &run)
  {
    status.ran                       = true;
    const fs::path           folder  = parent / status.folder;
    std::string             &message = status.message;
    double                  &seconds = status.seconds;
    dealii::ParameterHandler prm;
    prepare(command, prm, settings, study);
    fs::create_directories(folder);
    {
      std::ofstream out(folder / "parameters.prm");
      prm.print_parameters(out,
                           dealii::ParameterHandler::ShortPRM
                             | dealii::ParameterHandler::KeepDeclarationOrder);
    }
    std::cout << "\n=== compax compare: " << study << " study in "
              << folder.filename().string() << "/ ===" << std::endl;
    const auto start = std::chrono::steady_clock::now();
    int        code  = success;
    try
      {
        code = run(prm, folder);
        if (code != success)
          message = "compax " + command.name() + " stopped with exit code "
                    + std::to_string(code)
                    + (code == not_converged ? " (did not converge)" : "");
      }
    catch (const InputError &e)
      {
        throw InputError("in the " + study
                         + " study compare sets up: " + e.what());
      }
    catch (const std::exception &e)
      {
        message = e.what();
        code    = not_converged;
      }
    seconds
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    if (!message.empty())
      std::cout << "compax compare: the " << study
                << " study failed: " << message << std::endl;
    status.code = code;
  }

  Settings
  tablet_settings(const CompareSetup            &c,
                  const coupling::DepositedFill &fill,
                  const std::vector<double>     &branches,
                  const bool                     fe2)
  {
    const double H_final
      = fill.height * fill.relative_density / c.comparison.final_density;
    std::ostringstream list;
    for (std::size_t k = 0; k < branches.size(); ++k)
      list << (k ? ", " : "") << number(branches[k]);
    Settings s = {
      {"Geometry/Die diameter", number(c.comparison.die_diameter)},
      {"Geometry/Fill height", number(fill.height)},
      {"Mesh/Radial cells", std::to_string(fe2 ? c.fe2_cells : c.tablet_cells)},
      {"Material/Model", fe2 ? "multiscale-fe2" : "multiscale-database"},
      {"Material/Initial relative density", number(fill.relative_density)},
      // The particle die's walls are frictionless during compaction and
      // unloading; mu enters only the ejection pressure (Sec. 5.4).
      {"Die/Wall friction coefficient", "0"},
      {"Process/Compaction displacement", number(fill.height - H_final)},
      {"Process/Compaction steps",
       std::to_string(fe2 ? c.fe2_steps : c.tablet_steps)},
      {"Process/Unloading displacement", number(fe2 ? 0.0 : 0.4 * H_final)},
      {"Process/Unloading steps",
       std::to_string(fe2 ? 0 : c.tablet_unloading_steps)},
      {"Process/Ejection steps", "0"},
      {"Output/Write fields", "false"},
      {"Output/Write HDF5", "false"},
      {"Output/Checkpoint interval", "0"},
      {"Multiscale/Packing/Number of particles",
       std::to_string(fe2 ? c.fe2_particles : c.rve_particles)},
      {"Multiscale/Packing/Seed", std::to_string(c.rve_seed)},
      {"Multiscale/Packing/Initial relative density",
       number(fill.relative_density)},
      {"Multiscale/Paths/Final relative density", number(c.rve_final_density)},
      {"Multiscale/Paths/Branch densities", list.str()},
      {"Multiscale/Paths/Compaction strain step", number(c.rve_strain_step)},
      {"Multiscale/Paths/Shear steps", std::to_string(c.rve_shear_steps)}};
    if (fe2)
      {
        s.emplace_back("Multiscale/Pool size", std::to_string(c.fe2_pool));
        s.emplace_back("Multiscale/Tangent floor modulus", number(c.fe2_floor));
        s.emplace_back("Solver/Max step cuts", std::to_string(c.fe2_cuts));
      }
    for (const auto &[entry, value] : c.material)
      s.emplace_back("Multiscale/" + entry, value);
    for (const auto &[entry, value] : c.bonding)
      s.emplace_back("Multiscale/" + entry, value);
    return s;
  }
} // namespace compax::cli
