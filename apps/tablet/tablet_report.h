#pragma once

#include "coupling/tablet_study.h"

#include <filesystem>

namespace compax::cli
{
  /// The lines `compax tablet` prints about a run, from what the study
  /// gives (rank 0 calls them).

  /// The model, mesh and compact before the first step.
  template <int dim>
  void
  print_tablet_header(const coupling::TabletStudy<dim> &study,
                      const fem::MaterialModel         &material,
                      unsigned int                      ranks);

  /// One line per converged step.
  void
  print_tablet_step(const coupling::TabletProgress &progress);

  /// The FE2 time share, if any, and the extremes of the cycle (the stages
  /// @p process has).
  void
  print_tablet_summary(const coupling::TabletStudyResult &result,
                       const fem::TabletProcess          &process);

  /// tablet.png of tablet.csv in @p folder, with its gnuplot script.
  void
  plot_tablet(const std::filesystem::path &folder);
} // namespace compax::cli
