#include "fem/tablet_geometry.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
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
    upper_punch.validate(radius());
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
    prm.declare_entry("Cup depth",
                      "0",
                      Double(0.0),
                      "Depth h_c of the spherical cup of a concave upper "
                      "punch; 0: flat face [m].");
    prm.declare_entry("Cup radius of curvature",
                      "0",
                      Double(0.0),
                      "Radius of curvature R_c of the cup [m].");
    prm.declare_entry("Mesh file",
                      "",
                      dealii::Patterns::Anything(),
                      "Gmsh .msh file of the compact; empty: built-in mesh.");
  }

  void
  TabletGeometry::parse_parameters(dealii::ParameterHandler &prm)
  {
    die_diameter           = prm.get_double("Die diameter");
    fill_height            = prm.get_double("Fill height");
    n_radial_cells         = prm.get_integer("Radial cells");
    n_axial_cells          = prm.get_integer("Axial cells");
    upper_punch.cup_depth  = prm.get_double("Cup depth");
    upper_punch.cup_radius = prm.get_double("Cup radius of curvature");
    mesh_file              = prm.get("Mesh file");
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

  namespace
  {
    /// Radius of @p p from the z axis (r = x in the r-z plane).
    template <int dim>
    double
    radius_of(const dealii::Point<dim> &p)
    {
      return dim == 2 ? std::abs(p[0]) : std::hypot(p[0], p[1]);
    }

    /// Stretches every column of cells of a compact built with its upper
    /// face at z = H to the face of the upper punch.
    template <int dim>
    void
    map_to_upper_punch(dealii::Triangulation<dim> &tria,
                       const TabletGeometry       &geometry)
    {
      if (geometry.upper_punch.is_flat())
        return;
      const double H = geometry.fill_height;
      dealii::GridTools::transform(
        [&geometry, H](const dealii::Point<dim> &p) {
          dealii::Point<dim> q = p;
          q[dim - 1] *= 1.0 + geometry.upper_punch.height(radius_of(p)) / H;
          return q;
        },
        tria);
    }

    void
    build_axisymmetric_compact(dealii::Triangulation<2> &tria,
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
  } // namespace

  void
  make_axisymmetric_compact(dealii::Triangulation<2> &tria,
                            const TabletGeometry     &geometry)
  {
    build_axisymmetric_compact(tria, geometry);
    map_to_upper_punch(tria, geometry);
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
    map_to_upper_punch(tria, geometry);
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
    map_to_upper_punch(tria, geometry);
  }

  namespace
  {
    const char *
    boundary_name(const dealii::types::boundary_id id)
    {
      switch (id)
        {
          case axis:
            return "axis";
          case die_wall:
            return "die wall";
          case lower_punch:
            return "lower punch";
          case upper_punch:
            return "upper punch";
          case symmetry_x:
            return "symmetry plane x = 0";
          case symmetry_y:
            return "symmetry plane y = 0";
          default:
            return "unknown";
        }
    }

    std::string
    one_line(std::string text)
    {
      std::replace(text.begin(), text.end(), '\n', ' ');
      const auto first = text.find_first_not_of(' ');
      const auto last  = text.find_last_not_of(' ');
      return first == std::string::npos ? ""
                                        : text.substr(first, last - first + 1);
    }

    template <int dim>
    std::string
    describe(const dealii::Point<dim> &p)
    {
      std::ostringstream out;
      out << '(' << p[0];
      for (int d = 1; d < dim; ++d)
        out << ", " << p[d];
      out << ')';
      return out.str();
    }

    /// Checks the boundary of a compact read from a file, sets D and H.
    template <int dim>
    void
    check_compact_mesh(const dealii::Triangulation<dim> &tria,
                       TabletGeometry                   &geometry)
    {
      std::set<dealii::types::boundary_id> required
        = {die_wall, lower_punch, upper_punch};
      if (dim == 2)
        required.insert(axis);
      else
        required.insert({symmetry_x, symmetry_y});

      // Die radius and fill height from the die wall.
      double                               R = 0.0, H = 0.0, extent = 0.0;
      std::set<dealii::types::boundary_id> found;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          {
            for (const unsigned int v : face->vertex_indices())
              extent = std::max(extent, face->vertex(v).norm());
            if (!face->at_boundary())
              continue;
            const auto id = face->boundary_id();
            if (required.count(id) == 0)
              throw std::runtime_error(
                "boundary id " + std::to_string(id) + " on the face at "
                + describe(face->center()) + " is none of this model's ("
                + (dim == 2 ? "axis 0, die wall 1, lower punch 2, upper "
                              "punch 3"
                            : "die wall 1, lower punch 2, upper punch 3, "
                              "symmetry planes x = 0: 4, y = 0: 5")
                + "; faces without a physical id get 0)");
            found.insert(id);
            if (id == die_wall)
              for (const unsigned int v : face->vertex_indices())
                {
                  R = std::max(R, radius_of(face->vertex(v)));
                  H = std::max(H, face->vertex(v)[dim - 1]);
                }
          }
      for (const auto id : required)
        if (found.count(id) == 0)
          throw std::runtime_error("no boundary face has id "
                                   + std::to_string(id) + " ("
                                   + boundary_name(id) + ")");
      if (!(R > 0.0 && H > 0.0))
        throw std::runtime_error("the die wall (boundary id 1) has no extent");
      geometry.die_diameter = 2.0 * R;
      geometry.fill_height  = H;
      try
        {
          geometry.upper_punch.validate(R);
        }
      catch (const std::invalid_argument &e)
        {
          throw std::runtime_error(e.what());
        }

      // Every boundary vertex on the surface of its id.
      const double tol         = 1e-9 * extent;
      const double profile_tol = 1e-6 * R;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          {
            if (!face->at_boundary())
              continue;
            const auto id = face->boundary_id();
            for (const unsigned int v : face->vertex_indices())
              {
                const dealii::Point<dim> &p = face->vertex(v);
                const double              r = radius_of(p), z = p[dim - 1];
                // Distance of the vertex from its surface, and that surface.
                double      off = 0.0;
                std::string where;
                if (id == axis)
                  {
                    off   = r;
                    where = "on the axis r = 0";
                  }
                else if (id == die_wall)
                  {
                    off   = std::abs(r - R);
                    where = "on the die wall r = " + std::to_string(R) + " m";
                  }
                else if (id == lower_punch)
                  {
                    off   = std::abs(z);
                    where = "on the lower punch face z = 0";
                  }
                else if (id == symmetry_x)
                  {
                    off   = std::abs(p[0]);
                    where = "on the plane x = 0";
                  }
                else if (id == symmetry_y)
                  {
                    off   = std::abs(p[1]);
                    where = "on the plane y = 0";
                  }
                else
                  {
                    off = std::abs(z - H - geometry.upper_punch.height(r));
                    if (off > profile_tol)
                      {
                        std::ostringstream msg;
                        msg << "the upper punch face (boundary id 3) does not "
                               "follow the punch profile (land at the die "
                               "wall top z = "
                            << H << " m, cup depth "
                            << geometry.upper_punch.cup_depth
                            << " m, cup radius of curvature "
                            << geometry.upper_punch.cup_radius
                            << " m): its vertex " << describe(p) << " is "
                            << off
                            << " m off; give the cup of the mesh in Cup "
                               "depth and Cup radius of curvature";
                        throw std::runtime_error(msg.str());
                      }
                    continue;
                  }
                if (off > tol)
                  throw std::runtime_error(
                    "a vertex of the " + std::string(boundary_name(id))
                    + " (boundary id " + std::to_string(id) + ") at "
                    + describe(p) + " is not " + where);
              }
          }
    }
  } // namespace

  template <int dim>
  void
  read_compact_mesh(dealii::Triangulation<dim> &tria, TabletGeometry &geometry)
  {
    const std::string &file = geometry.mesh_file;
    std::ifstream      in(file);
    if (!in)
      throw std::runtime_error("cannot open the mesh file '" + file + "'");
    dealii::Triangulation<dim> coarse;
    const std::string kind = dim == 2 ? "a 2-D Gmsh mesh of r-z quadrilaterals"
                                      : "a 3-D Gmsh mesh of hexahedra";
    try
      {
        dealii::GridIn<dim> grid_in;
        grid_in.attach_triangulation(coarse);
        grid_in.read_msh(in);
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        throw std::runtime_error("'" + file + "' is not " + kind
                                 + " that deal.II reads: "
                                 + one_line(info.str()));
      }
    catch (const std::exception &e)
      {
        throw std::runtime_error("'" + file + "' is not " + kind
                                 + " that deal.II reads: "
                                 + one_line(e.what()));
      }
    if (coarse.n_active_cells() == 0
        || !coarse.all_reference_cells_are_hyper_cube())
      throw std::runtime_error("'" + file + "' is not " + kind
                               + " (use Recombine and a structured or "
                                 "transfinite mesh in Gmsh)");
    try
      {
        check_compact_mesh(coarse, geometry);
      }
    catch (const std::runtime_error &e)
      {
        throw std::runtime_error("'" + file + "': " + e.what());
      }
    tria.copy_triangulation(coarse);
    tria.reset_all_manifolds();
    tria.set_all_manifold_ids(dealii::numbers::flat_manifold_id);
    if constexpr (dim == 3)
      attach_die_wall_manifold(tria);
    // Refinement follows the cup: faces wholly inside it lie on its sphere.
    const PunchProfile &cup = geometry.upper_punch;
    if (!cup.is_flat())
      {
        const double a = cup.cup_edge_radius() * (1.0 + 1e-9);
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == upper_punch)
              {
                bool inside = true;
                for (const unsigned int v : face->vertex_indices())
                  inside = inside && radius_of(face->vertex(v)) <= a;
                if (inside)
                  face->set_all_manifold_ids(punch_cup_manifold);
              }
        dealii::Point<dim> centre;
        centre[dim - 1] = geometry.fill_height + cup.cup_depth - cup.cup_radius;
        tria.set_manifold(punch_cup_manifold,
                          dealii::SphericalManifold<dim>(centre));
      }
  }

  template <int dim>
  void
  make_compact(dealii::Triangulation<dim> &tria,
               TabletGeometry             &geometry,
               const unsigned int          n_global_refinements)
  {
    if (!geometry.mesh_file.empty())
      {
        read_compact_mesh(tria, geometry);
        tria.refine_global(n_global_refinements);
      }
    else if constexpr (dim == 2)
      {
        build_axisymmetric_compact(tria, geometry);
        tria.refine_global(n_global_refinements);
        map_to_upper_punch(tria, geometry);
      }
    else
      make_quarter_cylindrical_compact(tria, geometry, n_global_refinements);
  }

  template void
  make_compact(dealii::Triangulation<2> &, TabletGeometry &, unsigned int);
  template void
  make_compact(dealii::Triangulation<3> &, TabletGeometry &, unsigned int);
  template void
  read_compact_mesh(dealii::Triangulation<2> &, TabletGeometry &);
  template void
  read_compact_mesh(dealii::Triangulation<3> &, TabletGeometry &);
} // namespace compax::fem
