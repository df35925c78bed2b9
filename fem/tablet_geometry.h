#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

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

  /**
   * The powder column in a cylindrical die before (or at any state of)
   * compaction: a cylinder of diameter D filled to height H, its lower face
   * on the lower punch at z = 0.
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

    /// R = D/2 [m].
    double
    radius() const
    {
      return 0.5 * die_diameter;
    }

    /// Cells along z actually used (resolves n_axial_cells = 0).
    unsigned int
    axial_cells() const;

    /// Throws std::invalid_argument unless D > 0, H > 0 and n_radial > 0.
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
   * integrals with the axisymmetric measure 2 pi r dr dz.
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
} // namespace compax::fem
