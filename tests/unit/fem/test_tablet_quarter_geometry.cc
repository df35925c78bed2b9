// The quarter cylinder of the 3-D tablet model: its symmetry planes, punch
// faces and die wall carry their ids, and the volume is a quarter of the
// cylinder's.
#include "fem/tablet_geometry.h"

#include <deal.II/base/numbers.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace fem = compax::fem;

TEST(TabletQuarterGeometry, BoundaryIdsAndVolume)
{
  fem::TabletGeometry g;
  g.die_diameter = 10e-3;
  g.fill_height  = 6e-3;
  dealii::Triangulation<3> tria;
  fem::make_quarter_cylindrical_compact(tria, g, 2);
  const double R = g.radius(), H = g.fill_height, pi = dealii::numbers::PI;

  std::map<dealii::types::boundary_id, double> area;
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary())
        {
          const auto c = face->center(/*respect_manifold=*/true);
          switch (face->boundary_id())
            {
              case fem::symmetry_x:
                EXPECT_NEAR(c[0], 0.0, 1e-12);
                break;
              case fem::symmetry_y:
                EXPECT_NEAR(c[1], 0.0, 1e-12);
                break;
              case fem::lower_punch:
                EXPECT_NEAR(c[2], 0.0, 1e-12);
                break;
              case fem::upper_punch:
                EXPECT_NEAR(c[2], H, 1e-12);
                break;
              case fem::die_wall:
                EXPECT_NEAR(std::hypot(c[0], c[1]), R, 1e-12);
                break;
              default:
                ADD_FAILURE() << "id " << int(face->boundary_id());
            }
          area[face->boundary_id()] += face->measure();
        }
  ASSERT_EQ(area.size(), 5u);
  // Symmetry planes are the flat rectangles R x H.
  EXPECT_NEAR(area.at(fem::symmetry_x) / (R * H), 1.0, 1e-12);
  EXPECT_NEAR(area.at(fem::symmetry_y) / (R * H), 1.0, 1e-12);
  // A quartic mapping follows the die-wall manifold: a quarter cylinder.
  const dealii::MappingQ<3> mapping(4);
  EXPECT_NEAR(dealii::GridTools::volume(tria, mapping) / (pi * R * R * H / 4),
              1.0,
              1e-4);
}
