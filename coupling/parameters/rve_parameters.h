#pragma once

#include "dem/rve/homogenization.h"
#include "dem/rve/nonlocal_rve_loading.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"
#include "dem/rve/rve_path_study.h"
#include "dem/solver/contact_model.h"

#include <deal.II/base/parameter_handler.h>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace compax::coupling
{
  /// The macroscopic strain paths of `compax rve` (Path = csv is
  /// RvePath::increments).
  using RvePath = dem::RveStrainPath;

  /// Everything `compax rve` reads from its .prm, in the library's types:
  /// the options of the path study (strain path, tangents and their
  /// finite-difference checks, solvers, Stop after steps) and what the
  /// command adds around it.
  struct RveStudy : dem::RvePathStudyOptions
  {
    explicit RveStudy(dem::ContactModel model)
        : model(std::move(model))
    {
    }

    dem::ContactModel        model;
    dem::PeriodicPackingSpec packing;
    /// How the size distribution was given (for the log).
    std::string size_description;

    /// The CSV of the strain increments of Path = csv.
    std::string csv_file;
    /// VTU snapshots every this many steps (0: none).
    int snapshot_interval = 0;

    /// Particle counts of a cell-size study; empty: one run.
    std::vector<std::size_t> cell_sizes;

    int         checkpoint_interval = 0;
    std::string resume_from;
    /// The canonical text of the entries a checkpoint must have been
    /// written with to be resumed (all but Checkpoints and Size study; the
    /// strain increments file by its content).
    std::string resume_parameters;
  };

  /// A periodic cell to generate: its contact model and packing.
  struct RveCell
  {
    dem::ContactModel        model;
    dem::PeriodicPackingSpec packing;
    /// How the size distribution was given (for the log).
    std::string size_description;
  };

  /// Declares the subsections Material, Bonding and Packing of a cell
  /// (shared by `compax rve` and `compax database`), Packing/Protocol with
  /// the default `protocol` (deposited or compressed-gas).
  void
  declare_rve_cell_parameters(dealii::ParameterHandler &prm,
                              const std::string        &protocol = "deposited");

  /// Reads them; throws InputError naming the entry.
  RveCell
  get_rve_cell(dealii::ParameterHandler &prm);

  /**
   * Packing/Protocol = deposited: throws InputError naming
   * `prefix`Packing/Initial relative density if it lies below the density
   * of the deposited cell of `packing` with seed packing.seed + k for any
   * k in [0, seeds) (builds the deposits: about a second per 500
   * spheres). Nothing for compressed-gas.
   */
  void
  check_deposit_density(const dem::PeriodicPackingSpec &packing,
                        unsigned int                    seeds  = 1,
                        const std::string              &prefix = "");

  /// The InputError of check_deposit_density() for a deposit of relative
  /// density `deposit` [-].
  [[noreturn]] void
  reject_deposit_density(const dem::PeriodicPackingSpec &packing,
                         double                          deposit,
                         const std::string              &prefix = "");

  /// Declares the subsection Solver of an RVE driven along a path, with
  /// @p consolidation ("none" or "frozen-history") the default of its
  /// Consolidation entry.
  void
  declare_rve_solver_parameters(dealii::ParameterHandler &prm,
                                const std::string &consolidation = "none");

  /// Reads it.
  dem::RveLoadingOptions
  get_rve_loading_options(dealii::ParameterHandler &prm);

  /// Declares the subsections Material, Bonding, Packing, Strain path,
  /// Output, Size study, Checkpoints, Solver.
  void
  declare_rve_parameters(dealii::ParameterHandler &prm);

  /// Reads and cross-checks them (and reads the CSV of a csv path); throws
  /// InputError naming the entry.
  RveStudy
  get_rve_study(dealii::ParameterHandler &prm);

  /// Voigt-ordered names of the strain-increment columns of a csv path.
  const std::vector<std::string> &
  strain_csv_columns();

  /**
   * Reads strain increments (tensor components eps_xx, eps_yy, eps_zz,
   * eps_yz, eps_xz, eps_xy, any column order, header required, '#'
   * comments and blank lines skipped). Throws InputError naming `entry`
   * and the line on a malformed file.
   */
  std::vector<Eigen::Matrix3d>
  read_strain_increments(const std::string &file, const std::string &entry);
} // namespace compax::coupling
