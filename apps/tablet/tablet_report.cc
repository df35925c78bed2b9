#include "apps/tablet/tablet_report.h"

#include "apps/common/gnuplot.h"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace compax::cli
{
  template <int dim>
  void
  print_tablet_header(const coupling::TabletStudy<dim> &study,
                      const fem::MaterialModel         &material,
                      const unsigned int                ranks)
  {
    const auto &solver = study.solver();
    const auto &g      = solver.geometry();
    std::cout << "compax tablet: "
              << (dim == 2 ? "axisymmetric" : "3-D quarter") << " model, "
              << solver.n_cells() << " cells, " << solver.n_dofs()
              << " unknowns, " << ranks << " MPI rank(s), material "
              << material.name() << '\n'
              << "  die diameter " << g.die_diameter * 1e3
              << " mm, fill height " << g.fill_height * 1e3 << " mm";
    if (!g.upper_punch.is_flat())
      std::cout << " at the die wall, concave upper punch (cup depth "
                << g.upper_punch.cup_depth * 1e3 << " mm, radius of curvature "
                << g.upper_punch.cup_radius * 1e3 << " mm)";
    if (!g.mesh_file.empty())
      std::cout << ", mesh " << g.mesh_file;
    std::cout << ", initial volume " << study.initial_volume() * 1e9
              << " mm^3\n";
  }

  template void
  print_tablet_header(const coupling::TabletStudy<2> &,
                      const fem::MaterialModel &,
                      unsigned int);
  template void
  print_tablet_header(const coupling::TabletStudy<3> &,
                      const fem::MaterialModel &,
                      unsigned int);

  void
  print_tablet_step(const coupling::TabletProgress &p)
  {
    std::printf("step %4u/%u %-10s rho %.4f  upper %8.2f MPa  wall "
                "%7.2f MPa  lower %9.2f N  Newton %2u  %.1f s, ~%.0f "
                "s left\n",
                p.step.index,
                p.n_steps,
                fem::stage_name(p.step.stage).c_str(),
                p.step.mean_relative_density,
                p.upper_punch_pressure * 1e-6,
                p.die_wall_pressure * 1e-6,
                p.step.forces.lower_punch_force,
                p.step.newton_iterations,
                p.elapsed,
                p.left);
    std::fflush(stdout);
  }

  void
  print_tablet_summary(const coupling::TabletStudyResult &r,
                       const fem::TabletProcess          &process)
  {
    const coupling::TabletSummary &summary = r.summary;
    if (r.fe2)
      {
        const auto        &f = *r.fe2;
        std::ostringstream out;
        out << std::setprecision(4) << "RVE solves: " << f.solves << " ("
            << f.continuations << " by continuation, " << f.failures
            << " failed), " << f.seconds_all_ranks << " s on all ranks, "
            << f.seconds_busiest_rank << " s on the busiest rank, of "
            << f.wall_seconds << " s wall ("
            << 100.0 * f.seconds_busiest_rank / std::max(f.wall_seconds, 1e-300)
            << " %; the rest is the FEM: assembly, linear solves, output); "
            << "pool consolidated at start-up in " << f.pool_seconds << " s\n";
        std::cout << out.str();
      }
    std::cout << "Tablet cycle " << (r.converged ? "completed" : "STOPPED")
              << ":\n  max upper punch pressure     "
              << summary.max_upper_pressure * 1e-6
              << " MPa\n  rel. density at max pressure "
              << summary.density_at_max << " (in die)\n";
    if (process.unloading_steps > 0)
      std::cout << "  rel. density after unloading " << summary.density_unloaded
                << " (in die)\n  residual die-wall pressure   "
                << summary.residual_wall * 1e-6 << " MPa\n";
    if (process.ejection_steps > 0)
      std::cout << "  peak ejection force          "
                << summary.peak_ejection_force
                << " N\n  rel. density out of die      "
                << summary.density_out_of_die
                << (summary.ejected ? "" : " (tablet still in the die)")
                << "\n  mean stress out of die       "
                << summary.mean_stress_out_of_die * 1e-6
                << " MPa (tr sigma / 3 over the tablet, tension > 0)\n";
    if (r.fe2)
      std::cout << "  FE2 floor's mean stress      "
                << r.fe2->floor_mean_stress * 1e-6
                << " MPa (the RVEs carry the rest)\n";
  }

  void
  plot_tablet(const std::filesystem::path &folder)
  {
    render_png(folder,
               "tablet.gp",
               "set datafile separator ','\n"
               "set key autotitle columnhead\n"
               "set multiplot layout 2,1\n"
               "set xlabel 'time [s]'\n"
               "set ylabel 'pressure [MPa]'\n"
               "plot 'tablet.csv' using 2:($6/1e6) with lines lw 2 "
               "title 'upper punch', '' using 2:($7/1e6) with lines lw "
               "2 title 'lower punch', '' using 2:($8/1e6) with lines "
               "lw 2 title 'die wall'\n"
               "set ylabel 'ejection force [N]'\n"
               "plot 'tablet.csv' using 2:9 with lines lw 2 title "
               "'ejection force'\n"
               "unset multiplot\n",
               "tablet.png");
  }
} // namespace compax::cli
