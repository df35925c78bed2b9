#include "apps/crystal/crystal_command.h"

#include "apps/cli/input_error.h"
#include "apps/cli/parameters.h"
#include "apps/common/gnuplot.h"
#include "dem/crystals/crystal_compaction.h"
#include "io/csv_writer.h"

#include <deal.II/base/utilities.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace compax::cli
{
  namespace
  {
    using dem::CrystalConfiguration;
    using dem::CrystalFormulation;


    /// A comma-separated entry as its non-empty items.
    std::vector<std::string>
    items(dealii::ParameterHandler &prm, const std::string &name)
    {
      std::vector<std::string> list;
      for (const auto &item :
           dealii::Utilities::split_string_list(prm.get(name), ','))
        if (!item.empty())
          list.push_back(item);
      return list;
    }

    /// Everything the study needs, read from the parameters.
    struct CrystalStudy
    {
      std::vector<CrystalConfiguration> configurations;
      double                            radius;
      double                            youngs_modulus;
      /// The material's Poisson's ratio first, then the additional ones.
      std::vector<double>        poisson_ratios;
      double                     max_strain;
      double                     max_density;
      double                     preload;
      unsigned int               steps;
      dem::CrystalContactOptions contact;
    };

    /// Results of one configuration and Poisson's ratio.
    struct Curves
    {
      double           nu;
      dem::CrystalPath hertz;
      dem::CrystalPath nonlocal;
    };

    CrystalStudy
    read_study(dealii::ParameterHandler &prm)
    {
      CrystalStudy study;
      const auto   names = items(prm, "Configurations");
      if (names.empty())
        reject_entry("Configurations",
                     "''",
                     "give at least one of "
                       + dem::crystal_configuration_names(", "));
      for (const auto &name : names)
        try
          {
            study.configurations.push_back(
              dem::crystal_configuration_from_name(name));
          }
        catch (const std::invalid_argument &)
          {
            reject_entry("Configurations",
                         name,
                         "unknown configuration; allowed: "
                           + dem::crystal_configuration_names(", "));
          }
      prm.enter_subsection("Particle");
      study.radius         = prm.get_double("Radius");
      study.youngs_modulus = prm.get_double("Young's modulus");
      study.poisson_ratios.push_back(prm.get_double("Poisson's ratio"));
      prm.leave_subsection();
      for (const auto &item : items(prm, "Additional Poisson's ratios"))
        {
          const double nu = dealii::Utilities::string_to_double(item);
          if (!(nu > -1.0 && nu < 0.5))
            reject_entry("Additional Poisson's ratios",
                         item,
                         "every Poisson's ratio must lie in (-1, 0.5)");
          study.poisson_ratios.push_back(nu);
        }
      study.max_strain  = prm.get_double("Maximum deformation");
      study.max_density = prm.get_double("Maximum relative density");
      study.preload     = prm.get_double("Preload");
      study.steps       = prm.get_integer("Steps");
      prm.enter_subsection("Algorithm 1");
      study.contact.relative_tolerance = prm.get_double("Relative tolerance");
      study.contact.max_iterations     = prm.get_integer("Maximum iterations");
      prm.leave_subsection();

      for (const auto configuration : study.configurations)
        if (dem::crystal_uses_relative_density(configuration))
          {
            const double start = dem::make_crystal_lattice(configuration, 1.0)
                                   .relative_density(Eigen::Vector3d::Zero());
            if (!(study.max_density > start * (1.0 + 1e-9)))
              reject_entry("Maximum relative density",
                           format_number(study.max_density),
                           "must exceed the undeformed density "
                             + format_number(start) + " of the BCC crystal");
          }
      return study;
    }

    double
    max_strain_of(const CrystalStudy &study, CrystalConfiguration c)
    {
      return dem::crystal_uses_relative_density(c)
               ? dem::crystal_strain_at_density(c,
                                                study.max_density,
                                                study.preload)
               : study.max_strain;
    }

    /// Writes a quantity that may not exist (NaN) as an empty cell.
    void
    cell(io::CsvWriter &csv, const double value)
    {
      if (std::isnan(value))
        csv.empty();
      else
        csv << value;
    }

    std::string
    density_text(const double value)
    {
      return std::isnan(value) ? "none" : format_number(value);
    }

    class CrystalCommand : public Command
    {
    public:
      CrystalCommand()
          : Command(
            {"crystal",
             "granular crystals under Hertz and nonlocal contact "
             "(Gonzalez & Cuitino 2012)",
             "Compresses the granular crystals of Gonzalez & Cuitino "
             "2012, Sec. 4.1, under displacement control along z, with "
             "Hertz theory and with the nonlocal contact formulation "
             "(Eqs. 5, 9, 10, Algorithm 1): chain-1d (equivalent to a "
             "chain between rigid plates), square-2d and cubic-3d "
             "(periodic orthogonal to the load), square-2d-rotated (by "
             "pi/4), hexagonal-2d (close-packed), square-2d-preloaded "
             "(confined by eps0 in both directions first), "
             "bcc-hydrostatic and bcc-die. Every crystal is a Bravais "
             "lattice, so the affine deformation is in equilibrium and "
             "only the contacts of one particle are solved. The "
             "nonlocal formulation has a limit point beyond which it "
             "has no solution; its curves end there.\n\nWrites per "
             "configuration <name>.csv (nu, strain, relative_density, "
             "then for hertz_ and nonlocal_: load, lateral_x, "
             "lateral_y, coordination; and the discrepancy D of Eq. 16; "
             "loads are forces [N] on the faces of the deformed "
             "conventional cell, lateral reactions on the faces normal "
             "to x and y), <name>_load.png and <name>_discrepancy.png "
             "(like Figs. 10-17), contacts.csv (relative densities at "
             "which second and third contacts form, empty where none "
             "forms) and limits.csv (where the nonlocal formulation "
             "ends).\n\nBuilt-in default: the BCC crystal under "
             "hydrostatic and die compaction up to relative density "
             "1.1, rubber spheres of Sec. 3 (R = 0.01 m, E = 1.85 MPa, "
             "nu = 0.46) and nu = 0.45."})
      {
      }

      void
      declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry("Configurations",
                          "bcc-hydrostatic, bcc-die",
                          dealii::Patterns::Anything(),
                          "Comma-separated crystals to compress, among "
                            + dem::crystal_configuration_names(", ") + ".");
        prm.enter_subsection("Particle");
        declare_quantity(
          prm, "Radius", "0.01", positive(), "m", "Sphere radius R.");
        declare_quantity(prm,
                         "Young's modulus",
                         "1.85e6",
                         positive(),
                         "Pa",
                         "Young's modulus E of the spheres.");
        declare_quantity(prm,
                         "Poisson's ratio",
                         "0.46",
                         open(-1.0, 0.5),
                         "-",
                         "Poisson's ratio nu of the spheres; the load "
                         "plots use this value.");
        prm.leave_subsection();
        prm.declare_entry(
          "Additional Poisson's ratios",
          "0.45",
          dealii::Patterns::List(dealii::Patterns::Double(), 0),
          "Further Poisson's ratios, each in (-1, 0.5), for the "
          "discrepancy curves and contact densities (the discrepancy D "
          "depends on nu and the deformation only). Unit: -. May be "
          "empty.");
        declare_quantity(prm,
                         "Maximum deformation",
                         "0.1",
                         open(0.0, 0.5),
                         "-",
                         "Final load-axis deformation epsilon of the "
                         "chain, square, cubic, rotated, close-packed and "
                         "preloaded crystals (Sec. 4.1 stays below 10%).");
        declare_quantity(prm,
                         "Maximum relative density",
                         "1.1",
                         positive(),
                         "-",
                         "Final relative density (Eq. 19) of the BCC "
                         "crystals; must exceed the undeformed pi "
                         "sqrt(3)/8. Eq. (19) ignores the overlapping "
                         "caps, so it may exceed 1.");
        declare_quantity(prm,
                         "Preload",
                         "0.04",
                         RealInterval(0.0, false, 0.5, true),
                         "-",
                         "Confinement eps0 of square-2d-preloaded in both "
                         "directions before the load (Fig. 13).");
        prm.declare_entry("Steps",
                          "200",
                          dealii::Patterns::Integer(2, 1000000),
                          "Equal deformation increments of each path; the "
                          "formation of contacts is located by bisection "
                          "in between. Unit: -.");
        prm.enter_subsection("Algorithm 1");
        declare_quantity(prm,
                         "Relative tolerance",
                         "1e-13",
                         RealInterval(0.0, true, 1e-3, false),
                         "-",
                         "The fixed point stops when no nonlocal overlap "
                         "changes by more than this times R in a sweep.");
        prm.declare_entry("Maximum iterations",
                          "20000",
                          dealii::Patterns::Integer(1, 100000000),
                          "Sweeps before the nonlocal formulation is taken "
                          "to have no solution (limit point). Unit: -.");
        prm.leave_subsection();
      }

      void
      check_parameters(dealii::ParameterHandler &prm) const override
      {
        read_study(prm);
      }

      int
      run(dealii::ParameterHandler    &prm,
          const std::filesystem::path &folder) const override
      {
        const CrystalStudy study = read_study(prm);
        io::CsvWriter      contacts(folder / "contacts.csv",
                               {"configuration",
                                     "formulation",
                                     "nu",
                                     "second_contact_density",
                                     "third_contact_density"});
        io::CsvWriter      limits(
          folder / "limits.csv",
          {"configuration", "nu", "limit_strain", "limit_density"});
        for (const auto configuration : study.configurations)
          {
            const std::string name
              = dem::crystal_configuration_name(configuration);
            std::vector<Curves> curves;
            for (const double nu : study.poisson_ratios)
              curves.push_back(compute(study, configuration, nu));
            write_table(folder, study, configuration, curves);
            for (const auto &c : curves)
              {
                for (const auto formulation :
                     {CrystalFormulation::hertz, CrystalFormulation::nonlocal})
                  {
                    const dem::CrystalPath &path
                      = formulation == CrystalFormulation::hertz ? c.hertz
                                                                 : c.nonlocal;
                    contacts
                      << name
                      << std::string(formulation == CrystalFormulation::hertz
                                       ? "hertz"
                                       : "nonlocal")
                      << c.nu;
                    cell(contacts, path.formation_density(2));
                    cell(contacts, path.formation_density(3));
                    contacts.end_row();
                  }
                limits << name << c.nu;
                if (c.nonlocal.complete())
                  limits.empty().empty();
                else
                  limits << c.nonlocal.points.back().strain
                         << c.nonlocal.points.back().response.relative_density;
                limits.end_row();
              }
            print_summary(configuration, curves);
            plot(folder, configuration, curves);
          }
        contacts.close();
        limits.close();
        return success;
      }

    private:
      static Curves
      compute(const CrystalStudy        &study,
              const CrystalConfiguration configuration,
              const double               nu)
      {
        const dem::CrystalMaterial material{study.radius,
                                            study.youngs_modulus,
                                            nu};
        dem::CrystalPathOptions    options;
        options.max_strain = max_strain_of(study, configuration);
        options.steps      = study.steps;
        options.preload    = study.preload;
        options.contact    = study.contact;
        return {nu,
                dem::compute_crystal_path(
                  configuration, material, CrystalFormulation::hertz, options),
                dem::compute_crystal_path(configuration,
                                          material,
                                          CrystalFormulation::nonlocal,
                                          options)};
      }

      /// One row per deformation of the nonlocal path (which may end with a
      /// point off the grid, just below its limit point) and of the rest of
      /// the Hertz grid.
      static void
      write_table(const std::filesystem::path &folder,
                  const CrystalStudy          &study,
                  const CrystalConfiguration   configuration,
                  const std::vector<Curves>   &curves)
      {
        io::CsvWriter csv(
          folder / (dem::crystal_configuration_name(configuration) + ".csv"),
          {"nu",
           "strain",
           "relative_density",
           "hertz_load",
           "hertz_lateral_x",
           "hertz_lateral_y",
           "hertz_coordination",
           "nonlocal_load",
           "nonlocal_lateral_x",
           "nonlocal_lateral_y",
           "nonlocal_coordination",
           "discrepancy"});
        const dem::CrystalLattice lattice
          = dem::make_crystal_lattice(configuration, study.radius);
        for (const auto &c : curves)
          {
            dem::CrystalContacts hertz(lattice,
                                       {study.radius,
                                        study.youngs_modulus,
                                        c.nu},
                                       CrystalFormulation::hertz,
                                       study.contact);
            const auto row = [&](const dem::CrystalPathPoint *nonlocal,
                                 const double                 strain) {
              const Eigen::Vector3d strains
                = dem::crystal_cell_strains(configuration,
                                            strain,
                                            study.preload);
              const dem::CrystalResponse h = hertz.solve(strains);
              csv << c.nu << strain << h.relative_density;
              cell(csv, h.face_force[2]);
              cell(csv, h.face_force[0]);
              cell(csv, h.face_force[1]);
              csv << static_cast<long long>(h.coordination);
              if (nonlocal)
                {
                  const auto &r = nonlocal->response;
                  cell(csv, r.face_force[2]);
                  cell(csv, r.face_force[0]);
                  cell(csv, r.face_force[1]);
                  csv << static_cast<long long>(r.coordination);
                  if (h.face_force[2] > 0.0)
                    csv << (r.face_force[2] - h.face_force[2])
                             / h.face_force[2];
                  else
                    csv.empty();
                }
              else
                csv.empty().empty().empty().empty().empty();
              csv.end_row();
            };
            for (const auto &point : c.nonlocal.points)
              row(&point, point.strain);
            const double last = c.nonlocal.points.empty()
                                  ? -1.0
                                  : c.nonlocal.points.back().strain;
            for (const auto &point : c.hertz.points)
              if (point.strain > last)
                row(nullptr, point.strain);
          }
        csv.close();
      }

      static void
      print_summary(const CrystalConfiguration configuration,
                    const std::vector<Curves> &curves)
      {
        const std::string name = dem::crystal_configuration_name(configuration);
        std::cout << name << '\n';
        for (const auto &c : curves)
          {
            std::cout << "  nu = " << c.nu << '\n';
            for (const auto *path : {&c.hertz, &c.nonlocal})
              {
                std::cout << "    "
                          << (path == &c.hertz ? "hertz   " : "nonlocal")
                          << "  contacts form at relative density:";
                for (std::size_t k = 0; k < path->formations.size(); ++k)
                  {
                    const auto &f = path->formations[k];
                    std::cout << (k ? "," : "") << " #" << k + 1 << ' '
                              << f.relative_density << " (eps " << f.strain
                              << ", " << f.contacts << " neighbours at "
                              << f.distance << " diameters)";
                  }
                std::cout << '\n';
              }
            std::cout << "    second contacts: hertz "
                      << density_text(c.hertz.formation_density(2))
                      << ", nonlocal "
                      << density_text(c.nonlocal.formation_density(2))
                      << "; third contacts: hertz "
                      << density_text(c.hertz.formation_density(3))
                      << ", nonlocal "
                      << density_text(c.nonlocal.formation_density(3)) << '\n';
            if (!c.nonlocal.complete() && !c.nonlocal.points.empty())
              std::cout << "    nonlocal formulation: no solution beyond eps = "
                        << c.nonlocal.points.back().strain
                        << ", relative density "
                        << c.nonlocal.points.back().response.relative_density
                        << " (limit point of Algorithm 1)\n";
          }
      }

      static void
      plot(const std::filesystem::path &folder,
           const CrystalConfiguration   configuration,
           const std::vector<Curves>   &curves)
      {
        const std::string name = dem::crystal_configuration_name(configuration);
        const bool density  = dem::crystal_uses_relative_density(configuration);
        const std::string x = density ? "3" : "2";
        const std::string xlabel
          = density ? "relative density rho_R [-]" : "deformation epsilon [-]";
        const dem::CrystalLattice lattice
          = dem::make_crystal_lattice(configuration, 1.0);
        const std::string file = "'" + name + ".csv'";
        const auto select = [](const double nu, const std::string &column) {
          return "(abs($1-(" + format_number(nu) + "))<1e-9 ? $" + column
                 + " : 1/0)";
        };

        // Load and lateral reactions at the material's Poisson's ratio.
        const double nu   = curves.front().nu;
        std::string  load = "set xlabel '" + xlabel
                           + "'\n"
                             "set ylabel 'force on the cell face [N]'\n"
                             "set key top left\n"
                             "set title '"
                           + name + ", nu = " + format_number(nu) + "'\nplot "
                           + file + " using " + x + ":" + select(nu, "4")
                           + " with lines dt 2 lw 2 lc 'black' title 'load, "
                             "Hertz', '' using "
                           + x + ":" + select(nu, "8")
                           + " with lines lw 2 lc 'black' title 'load, "
                             "nonlocal'";
        if (lattice.dimension >= 2)
          load += ", '' using " + x + ":" + select(nu, "5")
                  + " with lines dt 2 lw 2 lc 'gray50' title 'lateral x, "
                    "Hertz', '' using "
                  + x + ":" + select(nu, "9")
                  + " with lines lw 2 lc 'gray50' title 'lateral x, "
                    "nonlocal'";
        if (lattice.dimension == 3
            && configuration != CrystalConfiguration::bcc_hydrostatic)
          load += ", '' using " + x + ":" + select(nu, "10")
                  + " with lines dt 3 lw 2 lc 'red' title 'lateral y, "
                    "nonlocal'";
        render_png(folder, name + "_load.gp", load + "\n", name + "_load.png");

        std::string discrepancy = "set xlabel '" + xlabel
                                  + "'\n"
                                    "set ylabel 'discrepancy D, Eq. (16) [-]'\n"
                                    "set key top left\n"
                                    "set title '"
                                  + name + "'\nplot ";
        for (std::size_t i = 0; i < curves.size(); ++i)
          discrepancy += std::string(i ? ", " : "") + (i ? "''" : file)
                         + " using " + x + ":" + select(curves[i].nu, "12")
                         + " with lines lw 2 title 'nu = "
                         + format_number(curves[i].nu) + "'";
        render_png(folder,
                   name + "_discrepancy.gp",
                   discrepancy + "\n",
                   name + "_discrepancy.png");
      }
    };
  } // namespace

  std::unique_ptr<Command>
  make_crystal_command()
  {
    return std::make_unique<CrystalCommand>();
  }
} // namespace compax::cli
