#pragma once

#include "fem/fe_space.h"
#include "fem/material_model.h"
#include "fem/quadrature_history.h"
#include "fem/tablet_geometry.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace compax::fem
{
  /// Numerical settings of the tablet model.
  struct TabletSolverSettings
  {
    TabletGeometry geometry;
    /// Global refinements of the coarse mesh (r-z: n_radial x axial
    /// cells; 3-D: the quarter cylinder) [-].
    unsigned int refinements = 0;
    /// Polynomial degree of the displacement [-].
    unsigned int degree = 1;
    /// Relative density of the powder as filled [-].
    double initial_relative_density = 0.5;
    /// Coulomb friction coefficient of the die wall [-].
    double wall_friction = 0.0;
    /// If not empty: the friction coefficient as a function of the
    /// relative density of the compact at the wall, (density, mu) pairs in
    /// increasing density, interpolated linearly and held constant beyond
    /// the ends; replaces wall_friction.
    std::vector<std::pair<double, double>> wall_friction_table;
    /// Height of the die top above the lower punch's initial face [m]; a
    /// point above it has no die wall to touch. 0: the fill height.
    double die_top = 0.0;
    /**
     * Entry taper of the die bore: over this length below the die top the
     * bore radius grows linearly by die_top_taper_opening [m]. A tablet
     * then leaves the wall gradually instead of releasing its residual
     * radial stress in one step (real dies have such an entry chamfer).
     * 0: a sharp die top.
     */
    double die_top_taper_length  = 0.0;
    double die_top_taper_opening = 0.0;
    /// Contact penalty = factor x (largest current Young's modulus) /
    /// (smallest initial cell size) [-].
    double penalty_factor = 100.0;
    /// Tangential (stick) penalty as a multiple of the normal one [-]; a
    /// softer stick spring keeps Newton from cycling between stick and slip
    /// on load reversal.
    double tangential_penalty_ratio = 0.1;
    /// Newton: relative residual tolerance [-] (raised to the material's
    /// stress_resolution()) and iteration limit.
    double       tolerance      = 1e-8;
    unsigned int max_iterations = 30;
    /// Times a load increment may be halved before giving up [-].
    unsigned int max_step_cuts = 8;
    /// Print every Newton residual to stderr (rank 0).
    bool verbose = false;
    /// Trilinos Amesos direct solver. "Amesos_Klu" factorises on one rank
    /// (the matrix is gathered there); "Amesos_Mumps" would factorise in
    /// parallel but crashes in Debian 12's Trilinos build.
    std::string direct_solver = "Amesos_Klu";
    /// "direct" (Amesos) or "gmres-amg" (GMRES with ML algebraic multigrid,
    /// falling back to the direct solver when it fails): the iterative
    /// solver scales to large 3-D meshes and many ranks.
    std::string linear_solver = "direct";
  };

  /// Resultants of the converged state, for the whole tablet (the 3-D
  /// quarter model multiplies by 4). Forces [N] positive in compression.
  struct TabletForces
  {
    double upper_punch_force = 0.0;
    double lower_punch_force = 0.0;
    /// Integral of the die-wall contact pressure over the wall [N].
    double die_wall_normal_force = 0.0;
    /// Wall area in contact (pressure > 0) [m^2].
    double die_wall_contact_area = 0.0;
    /// Axial friction force the wall exerts on the compact, positive
    /// upwards [N].
    double die_wall_friction_force = 0.0;
    /// Fraction of the wall contact points that slide [-].
    double sliding_fraction = 0.0;
  };

  /// The files of one field output of TabletSolver::write_fields().
  struct FieldFiles
  {
    /// Name of the .pvtu record of the .vtu pieces (empty: not written).
    std::string vtu_record;
    /// Name of the .h5 file (empty: not written).
    std::string hdf5_file;
    /// Its entry for the .xdmf file that lists all steps (valid when
    /// hdf5_file is not empty).
    dealii::XDMFEntry xdmf;
  };

  /**
   * Writes the .xdmf file @p file that lists the HDF5 field outputs
   * @p entries of a dim-dimensional model (one per step, in time order) for
   * ParaView or VisIt, as deal.II's DataOutInterface::write_xdmf_file()
   * does (which needs a DataOut with patches); rank 0 writes.
   */
  template <int dim>
  void
  write_xdmf_record(const std::vector<dealii::XDMFEntry> &entries,
                    const std::filesystem::path          &file,
                    MPI_Comm                              communicator);

  /// The die-wall friction coefficient of @p settings at relative density
  /// @p rho.
  double
  wall_friction_coefficient(const TabletSolverSettings &settings, double rho);

  /**
   * Quasi-static die compaction, unloading and ejection of a powder compact
   * in a rigid cylindrical die: dim = 2 is the axisymmetric r-z model
   * (hoop strain and 2 pi r measure), dim = 3 the quarter cylinder with
   * symmetry planes. Displacement field FE_Q(degree)^dim on a
   * parallel::distributed mesh, Trilinos matrices and a direct solver
   * (Amesos KLU), so it runs under mpirun.
   *
   * Large deformation: updated Lagrangian, incremental. Each load increment
   * is solved on the configuration at its start (a MappingQEulerian with
   * the total displacement), with the small-strain increment sym(grad du)
   * and Cauchy stress; the residual of increment n+1 is
   * int B_n^T sigma_{n+1} dv_n - contact, whose Newton tangent
   * (material tangent + contact tangent) is exact, and the configuration is
   * updated after convergence, so equilibrium is restored on the moving
   * mesh with a lag of one increment and no drift. The density follows the
   * exact mass balance rho_{n+1} = rho_n / det(F_inc); the stress is
   * rotated by the increment's Hughes-Winget rotation at commit. This is
   * the choice of most die compaction codes (hypoelastic DPC, Abaqus
   * style): the cap law is rate-form anyway, and die compaction is nearly
   * coaxial, so the error is of the order of the strain increment (about 1%
   * per step here) on rotations only.
   *
   * The mesh is the built-in one or a Gmsh file (make_compact()); the
   * upper punch face is flat or a concave cup (TabletGeometry::upper_punch)
   * whose gap is the signed distance of the point to it along its normal,
   * evaluated at the point's current position with the exact tangent
   * (normal stiffness plus the turning of the normal on the cup sphere).
   * The powder is at the initial relative density everywhere, so its mass
   * is that density times the volume of the mesh.
   *
   * Contact: penalty with regularised Coulomb friction (wall_contact()) on
   * the die wall (the powder fills the bore, so the gap is -u.n;
   * separation allowed; no wall where a point is above die_top, optionally
   * an entry taper below it), frictionless
   * penalty contact with the punch faces (which may separate), and a weak
   * bilateral spring (1e-6 of the penalty) to the lower punch that removes
   * the rigid axial motion of a tablet free of any contact.
   */
  template <int dim>
  class TabletSolver
  {
  public:
    TabletSolver(const TabletSolverSettings          &settings,
                 std::shared_ptr<const MaterialModel> material,
                 MPI_Comm                             communicator);

    /**
     * Moves the upper punch face to height @p upper (absent when
     * @p upper_present is false) and the lower punch face to @p lower
     * [m, from the initial lower punch face], in one increment, halving it
     * up to max_step_cuts times when Newton fails. Returns false (and keeps
     * the last converged state) if that does not suffice.
     */
    bool
    advance(double upper, double lower, bool upper_present = true);

    /// Forces of the last converged state.
    const TabletForces &
    forces() const
    {
      return converged_forces;
    }

    /// Mean relative density = initial density x initial / current volume.
    double
    mean_relative_density() const;

    /// Current volume of the whole tablet [m^3].
    double
    volume() const;

    /// Current punch positions [m].
    double
    upper_punch_position() const
    {
      return upper_position;
    }
    double
    lower_punch_position() const
    {
      return lower_position;
    }

    /// Geometry of the compact, D and H taken from a mesh file if read.
    const TabletGeometry &
    geometry() const
    {
      return settings.geometry;
    }

    /// Initial height of the upper punch face (of the land of a concave
    /// punch): the fill height [m].
    double
    initial_upper_punch_position() const
    {
      return settings.geometry.fill_height;
    }

    /// Area of a punch face pi R^2 [m^2].
    double
    punch_area() const;

    /// Newton iterations of the last advance() (all its sub-steps).
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

    /// Writes the fields as tablet_NNNN.vtu/.pvtu into @p folder; returns
    /// the .pvtu name.
    std::string
    write_fields(const std::filesystem::path &folder, unsigned int index) const;

    /**
     * Writes the fields (displacement at the nodes; relative density,
     * pressure, von Mises stress, stress components, plastic strains and
     * MPI rank per cell) on the deformed mesh into @p folder: as
     * tablet_NNNN.pvtu/.vtu if @p vtu, as one tablet_NNNN.h5 written by
     * all ranks (deal.II's parallel HDF5: datasets "nodes", "cells" and
     * one per field, each cell with its own nodes so that cell fields stay
     * exact) with its XDMF entry at @p time if @p hdf5. Collective.
     */
    FieldFiles
    write_fields(const std::filesystem::path &folder,
                 unsigned int                 index,
                 double                       time,
                 bool                         vtu,
                 bool                         hdf5) const;

    /**
     * Volume-averaged Cauchy stress [Pa] over the locally owned cells,
     * summed over ranks, in the current configuration: the
     * homogeneous-state tests read it, and its trace / 3 is the mean
     * stress column of tablet.csv. In equilibrium it equals the virial of
     * the boundary tractions over the volume, so it vanishes for a tablet
     * free of load (a residual stress field balances itself). Collective.
     */
    dealii::SymmetricTensor<2, 3>
    mean_stress() const;

    /**
     * Volume average over the current configuration of a tensor @p field
     * [its unit] of each quadrature point's committed material history
     * (e.g. a part of the stress that only the material model knows, such
     * as the FE2 floor's). Collective.
     */
    dealii::SymmetricTensor<2, 3>
    volume_average(const std::function<dealii::SymmetricTensor<2, 3>(
                     dealii::ArrayView<const double>)> &field) const;

    /**
     * Current positions of the mesh vertices on the boundary @p id, from
     * all ranks (a vertex shared by several faces appears once per face):
     * the shape of the tablet, e.g. its thickness on the axis and at the
     * rim.
     */
    std::vector<dealii::Point<dim>>
    boundary_positions(dealii::types::boundary_id id) const;

    /// Number of unknowns.
    dealii::types::global_dof_index
    n_dofs() const;

    /// Number of active cells.
    dealii::types::global_cell_index
    n_cells() const;

    /**
     * Writes the converged state (displacement, material and friction
     * history, punch positions, predictor) to @p folder as
     * solver.<rank>.bin, one file per MPI rank, and has the material write
     * the state it keeps outside the histories beside it
     * (MaterialModel::save_state()).
     */
    void
    save_state(const std::filesystem::path &folder) const;

    /**
     * Restores a state written by save_state() with the same settings,
     * material and number of MPI ranks (the distributed mesh is then
     * partitioned identically), the material's own state included
     * (MaterialModel::load_state()). Throws std::runtime_error otherwise.
     */
    void
    load_state(const std::filesystem::path &folder);

  private:
    bool
    solve_increment(double upper, double lower, bool upper_present);

    /// Assembles -residual (and the tangent); false on a material failure.
    bool
    assemble(bool with_matrix);

    void
    commit();

    /// Solves matrix delta = rhs with the configured solver.
    bool
    linear_solve(dealii::TrilinosWrappers::MPI::Vector  &delta,
                 dealii::TrilinosWrappers::SolverDirect &direct);

    double
    penalty() const;

    TabletSolverSettings                              settings;
    std::shared_ptr<const MaterialModel>              material;
    MPI_Comm                                          comm;
    dealii::parallel::distributed::Triangulation<dim> tria;
    dealii::FESystem<dim>                             fe;
    std::unique_ptr<FeSpace<dim>>                     space;
    dealii::AffineConstraints<double>                 constraints;
    dealii::QGauss<dim>                               cell_quadrature;
    dealii::QGauss<dim - 1>                           face_quadrature;
    dealii::TrilinosWrappers::SparseMatrix            matrix;
    dealii::TrilinosWrappers::MPI::Vector             rhs, du, du_ghost;
    dealii::TrilinosWrappers::MPI::Vector             u, u_ghost;
    /// Last converged increment and the punch motion that caused it, for
    /// the predictor of the next one.
    dealii::TrilinosWrappers::MPI::Vector last_du;
    double last_d_upper = 0.0, last_d_lower = 0.0;
    bool   last_upper_present = true;
    /// Locally owned axial displacement unknowns.
    dealii::IndexSet axial_dofs;
    /// Translations, the near null space for algebraic multigrid.
    std::vector<std::vector<bool>> rigid_modes;
    std::unique_ptr<
      dealii::MappingQEulerian<dim, dealii::TrilinosWrappers::MPI::Vector>>
      mapping;

    QuadratureHistory material_history;
    QuadratureHistory friction_history;

    double       upper_position, lower_position;
    bool         upper_active = true;
    double       target_upper = 0.0, target_lower = 0.0;
    bool         target_upper_present = true;
    double       eps_n = 0.0, h_min = 0.0, initial_volume = 0.0;
    double       internal_force_norm = 0.0;
    unsigned int iterations          = 0;
    TabletForces trial_forces, converged_forces;
  };
} // namespace compax::fem
