#include "fem/tablet_geometry.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using compax::fem::TabletGeometry;
namespace fem = compax::fem;

namespace
{
  TabletGeometry
  small_die()
  {
    TabletGeometry g;
    g.die_diameter   = 11.28e-3; // 1 cm^2 punch face
    g.fill_height    = 7.5e-3;
    g.n_radial_cells = 6;
    return g;
  }

  /// Checks that every boundary face carries the id of the plane its centre
  /// lies on, and returns the total face area (length in 2-D) per id.
  template <int dim>
  std::map<dealii::types::boundary_id, double>
  check_boundary_ids(const dealii::Triangulation<dim> &tria,
                     const TabletGeometry             &g)
  {
    const double                                 tol = 1e-12;
    std::map<dealii::types::boundary_id, double> measure;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        {
          if (!face->at_boundary())
            continue;
          const auto   c = face->center(/*respect_manifold=*/true);
          const double z = c[dim - 1];
          double       r = 0.0;
          for (int d = 0; d < (dim == 2 ? 1 : 2); ++d)
            r += c[d] * c[d];
          r = std::sqrt(r);
          switch (face->boundary_id())
            {
              case fem::axis:
                EXPECT_EQ(dim, 2);
                EXPECT_NEAR(r, 0.0, tol);
                break;
              case fem::die_wall:
                EXPECT_NEAR(r, g.radius(), tol);
                EXPECT_GT(z, 0.0);
                EXPECT_LT(z, g.fill_height);
                break;
              case fem::lower_punch:
                EXPECT_NEAR(z, 0.0, tol);
                break;
              case fem::upper_punch:
                EXPECT_NEAR(z, g.fill_height, tol);
                break;
              default:
                ADD_FAILURE()
                  << "unexpected boundary id " << int(face->boundary_id());
            }
          measure[face->boundary_id()] += face->measure();
        }
    return measure;
  }
} // namespace

TEST(TabletGeometry, AxisymmetricBoundaryIdsLieOnTheirPlanes)
{
  const TabletGeometry     g = small_die();
  dealii::Triangulation<2> tria;
  fem::make_axisymmetric_compact(tria, g);

  // Square-ish cells: H / (R / n_r) = 7.5 / (5.64 / 6) = 7.98 -> 8.
  EXPECT_EQ(g.axial_cells(), 8u);
  EXPECT_EQ(tria.n_active_cells(), 6u * 8u);

  const auto length = check_boundary_ids(tria, g);
  ASSERT_EQ(length.size(), 4u);
  EXPECT_NEAR(length.at(fem::axis), g.fill_height, 1e-15);
  EXPECT_NEAR(length.at(fem::die_wall), g.fill_height, 1e-15);
  EXPECT_NEAR(length.at(fem::lower_punch), g.radius(), 1e-15);
  EXPECT_NEAR(length.at(fem::upper_punch), g.radius(), 1e-15);
}

TEST(TabletGeometry, DistributedMeshHasTheSameBoundaries)
{
  const TabletGeometry                            g = small_die();
  dealii::parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  fem::make_axisymmetric_compact(tria, g);
  tria.refine_global(1);
  EXPECT_EQ(tria.n_global_active_cells(), 4u * 6u * 8u);
  const auto length = check_boundary_ids(tria, g);
  EXPECT_NEAR(length.at(fem::lower_punch), g.radius(), 1e-15);
}

TEST(TabletGeometry, CylinderBoundaryIdsAndVolume)
{
  const TabletGeometry     g = small_die();
  dealii::Triangulation<3> tria;
  fem::make_cylindrical_compact(tria, g, 2);
  const auto area = check_boundary_ids(tria, g);
  ASSERT_EQ(area.size(), 3u);
  EXPECT_EQ(area.count(fem::axis), 0u);

  const double R = g.radius(), H = g.fill_height, pi = dealii::numbers::PI;
  // The punch faces are flat cells whose boundary vertices sit on the
  // circle: deal.II's disk has 4 of them at 45 deg, each refinement bisects
  // the arcs, so the faces tile the regular N-gon, N = 4 * 2^2.
  const double N       = 16.0;
  const double polygon = 0.5 * N * R * R * std::sin(2.0 * pi / N);
  EXPECT_NEAR(area.at(fem::lower_punch) / polygon, 1.0, 1e-12);
  EXPECT_NEAR(area.at(fem::upper_punch) / polygon, 1.0, 1e-12);
  // ... and the die wall is that polygon's prism: perimeter times H.
  const double perimeter = N * 2.0 * R * std::sin(pi / N);
  EXPECT_NEAR(area.at(fem::die_wall) / (perimeter * H), 1.0, 1e-12);

  // A quartic mapping follows the cylindrical manifold; the volume then
  // converges to pi R^2 H far below the polygonal error.
  const dealii::MappingQ<3> mapping(4);
  EXPECT_NEAR(dealii::GridTools::volume(tria, mapping) / (pi * R * R * H),
              1.0,
              1e-6);
}

TEST(TabletGeometry, ParametersRoundTripAndValidate)
{
  dealii::ParameterHandler prm;
  TabletGeometry::declare_parameters(prm);
  prm.parse_input_from_string("set Die diameter = 0.008\n"
                              "set Fill height = 0.012\n"
                              "set Radial cells = 4\n");
  TabletGeometry g;
  g.parse_parameters(prm);
  EXPECT_DOUBLE_EQ(g.radius(), 0.004);
  EXPECT_DOUBLE_EQ(g.fill_height, 0.012);
  EXPECT_EQ(g.axial_cells(), 12u);

  g.die_diameter = 0.0;
  EXPECT_THROW(g.validate(), std::invalid_argument);
}
