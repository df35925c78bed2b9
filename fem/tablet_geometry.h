#pragma once

#include "fem/punch_profile.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <string>

namespace compax::fem
{
  /**
   * Boundary ids of the powder compact in its die. In the axisymmetric r-z
   * mesh the coordinates are (x, y) = (r, z): the symmetry axis is r = 0,
   * the die wall r = R, the lower punch face z = 0 and the upper punch face
   * z = H. The 3-D cylinder has no axis boundary.
   */
  enum BoundaryId : dealii::types::boundary_id
  {
    axis        = 0,
    die_wall    = 1,
    lower_punch = 2,
    upper_punch = 3,
    /// Symmetry planes x = 0 and y = 0 of the 3-D quarter model.
    symmetry_x = 4,
    symmetry_y = 5
  };

  /// Manifold id of the curved die wall of the 3-D cylinder.
  constexpr dealii::types::manifold_id die_wall_manifold = 0;
  /// Manifold id of the spherical cup of a concave upper punch in a mesh
  /// read from a file.
  constexpr dealii::types::manifold_id punch_cup_manifold = 1;

  /**
   * The powder column in a cylindrical die before (or at any state of)
   * compaction: a cylinder of diameter D filled to height H, its lower face
   * on the lower punch at z = 0. Under a concave upper punch the powder
   * also fills the punch cup: H is then the height at the die wall (the
   * punch land) and the column is H + h_c high on the axis.
   */
  struct TabletGeometry
  {
    /// Die diameter D [m].
    double die_diameter = 10.0e-3;
    /// Height of the powder column H (fill height) [m].
    double fill_height = 10.0e-3;
    /// Cells across the radius of the r-z mesh [-].
    unsigned int n_radial_cells = 8;
    /// Cells along the height; 0 picks the count that makes cells
    /// closest to square [-].
    unsigned int n_axial_cells = 0;
    /// Face of the upper punch (flat by default).
    PunchProfile upper_punch;
    /**
     * Gmsh .msh file of the compact (r-z quadrilaterals for the
     * axisymmetric model, hexahedra of the quarter cylinder in 3-D) with
     * the BoundaryId values as physical ids; empty: the built-in mesh.
     * read_compact_mesh() takes D and H from it.
     */
    std::string mesh_file;

    /// R = D/2 [m].
    double
    radius() const
    {
      return 0.5 * die_diameter;
    }

    /// Cells along z actually used (resolves n_axial_cells = 0).
    unsigned int
    axial_cells() const;

    /// Throws std::invalid_argument unless D > 0, H > 0, n_radial > 0 and
    /// the punch profile fits the die.
    void
    validate() const;

    /// Declares the entries (with units and ranges) of this struct in the
    /// current section of @p prm.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads the entries declared by declare_parameters().
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Fills the empty @p tria (a serial or a parallel::distributed
   * Triangulation<2>) with the r-z rectangle [0, R] x [0, H] of @p geometry,
   * subdivided into n_radial x axial_cells() rectangles, and sets the
   * BoundaryId of every boundary face. Integrals over it become volume
   * integrals with the axisymmetric measure 2 pi r dr dz. A concave upper
   * punch stretches each column of cells to its face: z -> z (H + c(r)) / H
   * with c the height of the face above its land.
   */
  void
  make_axisymmetric_compact(dealii::Triangulation<2> &tria,
                            const TabletGeometry     &geometry);

  /**
   * Fills the empty @p tria with the 3-D cylinder of radius R whose axis is
   * the z-axis, from z = 0 to z = H, with die_wall, lower_punch and
   * upper_punch boundary ids and a CylindricalManifold (id die_wall_manifold)
   * on the die wall so that refinement follows the circle. The cross-section
   * is deal.II's five-cell disk with round(H/R) coarse cells along z
   * (n_radial_cells and n_axial_cells apply to the r-z mesh only);
   * @p n_global_refinements refines it further.
   */
  void
  make_cylindrical_compact(dealii::Triangulation<3> &tria,
                           const TabletGeometry     &geometry,
                           unsigned int              n_global_refinements = 0);

  /**
   * Fills the empty @p tria with the quarter x >= 0, y >= 0 of the 3-D
   * cylinder of make_cylindrical_compact(): deal.II's three-cell quarter
   * disk extruded along z with cells about as tall as wide, boundary ids
   * die_wall, lower_punch, upper_punch, symmetry_x (x = 0) and symmetry_y
   * (y = 0), and the CylindricalManifold on the die wall;
   * @p n_global_refinements refines it further.
   */
  void
  make_quarter_cylindrical_compact(dealii::Triangulation<3> &tria,
                                   const TabletGeometry     &geometry,
                                   unsigned int n_global_refinements = 0);

  /**
   * Fills the empty @p tria with the compact of @p geometry for the model
   * of dimension dim (2: r-z, 3: quarter cylinder) refined
   * @p n_global_refinements times: read from geometry.mesh_file if set
   * (read_compact_mesh(), which also sets D and H in @p geometry; a
   * SphericalManifold on the punch cup makes refinement follow it),
   * otherwise built by make_axisymmetric_compact() or
   * make_quarter_cylindrical_compact() (a concave cup mapped after
   * refinement, so every vertex of the punch face lies on it).
   */
  template <int dim>
  void
  make_compact(dealii::Triangulation<dim> &tria,
               TabletGeometry             &geometry,
               unsigned int                n_global_refinements);

  /**
   * Reads the Gmsh file geometry.mesh_file into the empty @p tria and
   * checks that it is a compact of this model: quadrilaterals (2-D) or
   * hexahedra (3-D); boundary ids axis (r = 0, 2-D only), die_wall,
   * lower_punch (z = 0), upper_punch and, in 3-D, symmetry_x (x = 0) and
   * symmetry_y (y = 0), each present and on its surface; the upper punch
   * face on geometry.upper_punch with its land at the top of the die wall.
   * Sets geometry.die_diameter (2 x radius of the die wall) and
   * geometry.fill_height (top of the die wall) from the mesh. Throws
   * std::runtime_error saying what is wrong.
   */
  template <int dim>
  void
  read_compact_mesh(dealii::Triangulation<dim> &tria, TabletGeometry &geometry);
} // namespace compax::fem
