#pragma once

#include "coupling/tablet_study.h"
#include "fem/material_registry.h"
#include "fem/tablet_process.h"
#include "fem/tablet_solver.h"

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

/**
 * @file
 * The parameters of a tablet run (subsections Geometry, Mesh, Material,
 * Die, Process, Solver, Output), declared and read by the library, so that
 * a C++ caller builds the same TabletStudy from a .prm as `compax tablet`.
 */

namespace compax::coupling
{
  /// Everything a tablet run needs, read from the parameters.
  struct TabletSetup
  {
    /// Mesh/Model = quarter-3d (else the axisymmetric r-z model).
    bool                                      three_d = false;
    fem::TabletSolverSettings                 solver;
    fem::TabletProcess                        process;
    std::shared_ptr<const fem::MaterialModel> material;
    /// Output, checkpoints and resume (the caller sets the folder);
    /// parameters: the canonical text of the entries a checkpoint must
    /// have been written with to be resumed.
    TabletStudyOptions output;
    /// The name of a registered material without a factory (its caller
    /// builds it at run time, e.g. multiscale-fe2); empty otherwise.
    std::string deferred_material;
  };

  /**
   * Declares the tablet's subsections; Material/Model offers the names of
   * @p materials, whose own entries are declared in Material.
   */
  void
  declare_tablet_parameters(dealii::ParameterHandler    &prm,
                            const fem::MaterialRegistry &materials);

  /**
   * Reads and checks what declare_tablet_parameters() declared: every bad
   * entry (a mesh file that is no Gmsh mesh, a cup that does not fit, an
   * unreadable DPC table, a checkpoint that cannot be resumed, ...) is an
   * input::InputError naming it, before any output exists. Sets
   * Geometry/Mesh file to the absolute path of the mesh it read.
   */
  TabletSetup
  parse_tablet_parameters(dealii::ParameterHandler    &prm,
                          const fem::MaterialRegistry &materials);
} // namespace compax::coupling
