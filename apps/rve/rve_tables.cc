#include "apps/rve/rve_tables.h"

#include "coupling/parameters/voigt_columns.h"
#include "io/csv_writer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace compax::cli
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    std::size_t
    index_of(const std::vector<std::string> &names, const std::string &name)
    {
      const auto it = std::find(names.begin(), names.end(), name);
      if (it == names.end())
        throw std::logic_error("no column '" + name + "'");
      return it - names.begin();
    }
  } // namespace

  const std::vector<std::string> &
  rve_columns()
  {
    static const std::vector<std::string> names = [] {
      std::vector<std::string> n{"step", "stage", "relative_density"};
      for (const char *tensor : {"eps", "sigma"})
        for (std::string &column : coupling::voigt_columns(tensor))
          n.push_back(std::move(column));
      n.insert(n.end(),
               {"mean_pressure",
                "coordination_number",
                "coordination_without_rattlers",
                "rattler_fraction",
                "bonding_surface",
                "bonds",
                "bonds_formed",
                "bonds_broken",
                "jammed",
                "substeps",
                "cutbacks",
                "iterations",
                "residual"});
      return n;
    }();
    return names;
  }

  const std::vector<std::string> &
  moduli_columns()
  {
    static const std::vector<std::string> names = [] {
      std::vector<std::string> n{"step",
                                 "stage",
                                 "relative_density",
                                 "E",
                                 "nu",
                                 "bulk_modulus",
                                 "shear_modulus",
                                 "E_p",
                                 "nu_p",
                                 "E_z",
                                 "nu_zp",
                                 "G_zp"};
      // The transversely isotropic stiffness, tangent and affine.
      for (const std::string variant : {"", "_affine"})
        for (const char *component : {"C11", "C33", "C12", "C13", "C44"})
          n.push_back(component + variant);
      n.push_back("tangent_fd_error");
      return n;
    }();
    return names;
  }

  std::size_t
  rve_column(const std::string &name)
  {
    return index_of(rve_columns(), name);
  }

  std::size_t
  moduli_column(const std::string &name)
  {
    return index_of(moduli_columns(), name);
  }

  const std::vector<std::string> &
  timing_columns()
  {
    static const std::vector<std::string> names{"step",
                                                "stage",
                                                "step_seconds",
                                                "tangent_seconds"};
    return names;
  }

  std::vector<double>
  rve_row(const dem::RvePathStep &step)
  {
    std::vector<double>       row(rve_columns().size(), nan);
    const auto               &eps   = step.strain;
    const auto               &sigma = step.stress;
    const auto               &m     = step.measures;
    const dem::RveStepResult *r     = step.solve ? &*step.solve : nullptr;
    auto set = [&](const char *name, double v) { row[rve_column(name)] = v; };
    set("step", step.step);
    set("stage", step.unloading ? 1.0 : 0.0);
    set("relative_density", step.relative_density);
    set("eps_xx", eps(0, 0));
    set("eps_yy", eps(1, 1));
    set("eps_zz", eps(2, 2));
    set("eps_yz", eps(1, 2));
    set("eps_xz", eps(0, 2));
    set("eps_xy", eps(0, 1));
    set("sigma_xx", sigma(0, 0));
    set("sigma_yy", sigma(1, 1));
    set("sigma_zz", sigma(2, 2));
    set("sigma_yz", 0.5 * (sigma(1, 2) + sigma(2, 1)));
    set("sigma_xz", 0.5 * (sigma(0, 2) + sigma(2, 0)));
    set("sigma_xy", 0.5 * (sigma(0, 1) + sigma(1, 0)));
    set("mean_pressure", -sigma.trace() / 3.0);
    set("coordination_number", m.coordination_number);
    set("coordination_without_rattlers", m.coordination_without_rattlers);
    set("rattler_fraction", m.rattler_fraction);
    set("bonding_surface", m.bonding_surface);
    set("bonds", double(m.n_bonds));
    set("bonds_formed", r ? double(r->bonds.formed) : 0.0);
    set("bonds_broken", r ? double(r->bonds.broken) : 0.0);
    set("jammed", r ? double(r->jammed) : 0.0);
    set("substeps", r ? r->substeps : 0);
    set("cutbacks", r ? r->cutbacks : 0);
    set("iterations", r ? r->iterations : 0);
    set("residual", r ? r->relative_residual : 0.0);
    return row;
  }

  std::vector<double>
  moduli_row(const dem::RvePathModuli &m)
  {
    std::vector<double> row(moduli_columns().size(), nan);
    auto                set = [&](const std::string &name, double v) {
      row[moduli_column(name)] = v;
    };
    set("step", m.step);
    set("stage", m.unloading ? 1.0 : 0.0);
    set("relative_density", m.relative_density);
    set("E", m.isotropic.youngs_modulus);
    set("nu", m.isotropic.poisson_ratio);
    set("bulk_modulus", m.isotropic.bulk_modulus);
    set("shear_modulus", m.isotropic.shear_modulus);
    if (const auto &ti = m.transversely_isotropic)
      {
        set("E_p", ti->youngs_in_plane);
        set("nu_p", ti->poisson_in_plane);
        set("E_z", ti->youngs_axial);
        set("nu_zp", ti->poisson_axial_to_plane);
        set("G_zp", ti->shear_axial);
      }
    // C11 C33 C12 C13 C44 of the transversely isotropic parts.
    const int   entries[5][2] = {{0, 0}, {2, 2}, {0, 1}, {0, 2}, {3, 3}};
    const char *names[5]      = {"C11", "C33", "C12", "C13", "C44"};
    for (int k = 0; k < 5; ++k)
      {
        const auto [r, c] = entries[k];
        set(names[k], m.condensed_projection(r, c));
        set(std::string(names[k]) + "_affine", m.affine_projection(r, c));
      }
    set("tangent_fd_error", m.fd_error);
    return row;
  }

  std::vector<std::vector<double>>
  timing_rows(const dem::RvePathResult &result)
  {
    std::vector<std::vector<double>> rows;
    for (const dem::RvePathStep &s : result.steps)
      {
        double tangent = nan;
        for (const dem::RvePathModuli &m : result.moduli)
          if (m.step == s.step)
            tangent = m.seconds;
        rows.push_back(
          {double(s.step), s.unloading ? 1.0 : 0.0, s.seconds, tangent});
      }
    return rows;
  }

  void
  write_table(const std::filesystem::path            &file,
              const std::vector<std::string>         &columns,
              const std::vector<std::vector<double>> &rows)
  {
    io::CsvWriter     csv(file, columns);
    const std::size_t stage = index_of(columns, "stage");
    for (const auto &row : rows)
      {
        for (std::size_t k = 0; k < columns.size(); ++k)
          if (k == stage)
            csv << std::string(row[k] == 0.0 ? "loading" : "unloading");
          else if (std::isnan(row[k]))
            csv.empty();
          else if (columns[k] == "step" || columns[k] == "iterations"
                   || columns[k] == "substeps" || columns[k] == "cutbacks"
                   || columns[k] == "bonds" || columns[k] == "bonds_formed"
                   || columns[k] == "bonds_broken" || columns[k] == "jammed")
            csv << static_cast<long long>(row[k]);
          else
            csv << row[k];
        csv.end_row();
      }
    csv.close();
  }
} // namespace compax::cli
