#include "fem/tablet_geometry.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::fem
{
  unsigned int
  TabletGeometry::axial_cells() const
  {
    if (n_axial_cells > 0)
      return n_axial_cells;
    const double cell_width = radius() / n_radial_cells;
    return std::max(
      1u, static_cast<unsigned int>(std::lround(fill_height / cell_width)));
  }

  void
  TabletGeometry::validate() const
  {
    if (!(die_diameter > 0.0))
      throw std::invalid_argument("TabletGeometry: die diameter must be > 0");
    if (!(fill_height > 0.0))
      throw std::invalid_argument("TabletGeometry: fill height must be > 0");
    if (n_radial_cells == 0)
      throw std::invalid_argument(
        "TabletGeometry: need at least one radial cell");
  }

  void
  TabletGeometry::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    const TabletGeometry defaults;
    prm.declare_entry("Die diameter",
                      std::to_string(defaults.die_diameter),
                      Double(0.0),
                      "Inner diameter D of the cylindrical die [m].");
    prm.declare_entry("Fill height",
                      std::to_string(defaults.fill_height),
                      Double(0.0),
                      "Height H of the powder column in the die [m].");
    prm.declare_entry("Radial cells",
                      std::to_string(defaults.n_radial_cells),
                      Integer(1),
                      "Cells across the radius of the r-z mesh [-].");
    prm.declare_entry("Axial cells",
                      std::to_string(defaults.n_axial_cells),
                      Integer(0),
                      "Cells along the height; 0 makes the cells as close to "
                      "square as possible [-].");
  }

  void
  TabletGeometry::parse_parameters(dealii::ParameterHandler &prm)
  {
    die_diameter   = prm.get_double("Die diameter");
    fill_height    = prm.get_double("Fill height");
    n_radial_cells = prm.get_integer("Radial cells");
    n_axial_cells  = prm.get_integer("Axial cells");
    validate();
  }

  namespace
  {
    /// Sets the BoundaryId of each boundary face from its centre; @p
    /// has_axis tells whether r = 0 is a boundary (r-z mesh) or not (3-D).
    template <int dim>
    void
    colour_boundaries(dealii::Triangulation<dim> &tria,
                      const TabletGeometry       &geometry,
                      const bool                  quarter = false)
    {
      const double tol
        = 1e-10 * std::max(geometry.radius(), geometry.fill_height);
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          {
            if (!face->at_boundary())
              continue;
            const dealii::Point<dim> c = face->center();
            const double             z = c[dim - 1];
            if (std::abs(z) < tol)
              face->set_boundary_id(lower_punch);
            else if (std::abs(z - geometry.fill_height) < tol)
              face->set_boundary_id(upper_punch);
            else if (dim == 2 && std::abs(c[0]) < tol)
              face->set_boundary_id(axis);
            else if (dim == 3 && quarter && std::abs(c[0]) < tol)
              face->set_boundary_id(symmetry_x);
            else if (dim == 3 && quarter && std::abs(c[1]) < tol)
              face->set_boundary_id(symmetry_y);
            else
              face->set_boundary_id(die_wall);
          }
    }
  } // namespace

  void
  make_axisymmetric_compact(dealii::Triangulation<2> &tria,
                            const TabletGeometry     &geometry)
  {
    geometry.validate();
    const std::vector<unsigned int> repetitions
      = {geometry.n_radial_cells, geometry.axial_cells()};
    dealii::GridGenerator::subdivided_hyper_rectangle(
      tria,
      repetitions,
      dealii::Point<2>(0.0, 0.0),
      dealii::Point<2>(geometry.radius(), geometry.fill_height));
    colour_boundaries(tria, geometry);
  }

  namespace
  {
    /// The die wall of a 3-D compact follows the cylinder about the z axis
    /// when the mesh is refined.
    void
    attach_die_wall_manifold(dealii::Triangulation<3> &tria)
    {
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == die_wall)
            face->set_all_manifold_ids(die_wall_manifold);
      tria.set_manifold(
        die_wall_manifold,
        dealii::CylindricalManifold<3>(dealii::Tensor<1, 3>({0.0, 0.0, 1.0}),
                                       dealii::Point<3>(0.0, 0.0, 0.0)));
    }
  } // namespace

  void
  make_cylindrical_compact(dealii::Triangulation<3> &tria,
                           const TabletGeometry     &geometry,
                           const unsigned int        n_global_refinements)
  {
    geometry.validate();
    // Coarse cells of deal.II's disk are about R wide; match that along z.
    const unsigned int n_axial
      = std::max(1u,
                 static_cast<unsigned int>(
                   std::lround(geometry.fill_height / geometry.radius())));
    const double half_height = 0.5 * geometry.fill_height;
    dealii::GridGenerator::subdivided_cylinder(tria,
                                               n_axial,
                                               geometry.radius(),
                                               half_height);
    // deal.II's cylinder lies along x from -H/2 to H/2; the cyclic
    // permutation (x, y, z) -> (y, z, x + H/2) keeps the cells right-handed
    // and puts the axis on z with the lower punch at z = 0.
    dealii::GridTools::transform(
      [half_height](const dealii::Point<3> &p) {
        return dealii::Point<3>(p[1], p[2], p[0] + half_height);
      },
      tria);
    tria.reset_all_manifolds();
    tria.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
    colour_boundaries(tria, geometry);
    attach_die_wall_manifold(tria);
    tria.refine_global(n_global_refinements);
  }

  void
  make_quarter_cylindrical_compact(dealii::Triangulation<3> &tria,
                                   const TabletGeometry     &geometry,
                                   const unsigned int n_global_refinements)
  {
    geometry.validate();
    dealii::Triangulation<2> disk;
    dealii::GridGenerator::quarter_hyper_ball(disk,
                                              dealii::Point<2>(0.0, 0.0),
                                              geometry.radius());
    // The quarter disk's cells are about R/2 wide; match that along z.
    const unsigned int n_slices
      = std::max(1u,
                 static_cast<unsigned int>(std::lround(
                   2.0 * geometry.fill_height / geometry.radius())));
    dealii::GridGenerator::extrude_triangulation(disk,
                                                 n_slices + 1,
                                                 geometry.fill_height,
                                                 tria);
    tria.reset_all_manifolds();
    tria.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
    colour_boundaries(tria, geometry, /*quarter=*/true);
    attach_die_wall_manifold(tria);
    tria.refine_global(n_global_refinements);
  }
} // namespace compax::fem
