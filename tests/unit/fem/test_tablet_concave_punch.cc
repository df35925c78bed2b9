// Concave upper punches: the shipped Gmsh mesh against the closed-form
// volume of a cylinder with a spherical cap, rejected mesh files, and an
// elastic compact under a concave punch in a frictionless die (axial
// equilibrium, the flat-faced limit, the cup shape of the tablet).
#include "fem/isotropic_elasticity.h"
#include "fem/linear_elastic_material.h"
#include "fem/tablet_geometry.h"
#include "fem/tablet_solver.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace fem = compax::fem;

namespace
{
  constexpr double pi = dealii::numbers::PI;

  /// The cup of meshes/concave_punch_rz.geo.
  constexpr double cup_depth = 0.7e-3, cup_radius = 16e-3;
  constexpr double D = 10e-3, H = 7e-3;

  fem::TabletGeometry
  shipped_mesh()
  {
    fem::TabletGeometry g;
    g.mesh_file
      = std::string(COMPAX_SOURCE_DIR) + "/meshes/concave_punch_rz.msh";
    g.upper_punch.cup_depth  = cup_depth;
    g.upper_punch.cup_radius = cup_radius;
    return g;
  }

  /// Volume of revolution 2 pi int r dA of an r-z mesh, with the mapping
  /// @p degree (the quadrature is exact for the bilinear cells).
  double
  volume_of_revolution(const dealii::Triangulation<2> &tria,
                       const unsigned int              degree = 1)
  {
    const dealii::MappingQ<2> mapping(degree);
    dealii::FE_Nothing<2>     fe;
    dealii::QGauss<2>         quadrature(degree + 3);
    dealii::FEValues<2>       fv(mapping,
                           fe,
                           quadrature,
                           dealii::update_quadrature_points
                             | dealii::update_JxW_values);
    double                    V = 0.0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        fv.reinit(cell);
        for (const unsigned int q : fv.quadrature_point_indices())
          V += 2.0 * pi * fv.quadrature_point(q)[0] * fv.JxW(q);
      }
    return V;
  }

  /**
   * Upper bound of the volume of revolution between the cup arc and its
   * chords on the upper punch face: a chord of length L on a circle of
   * radius R_c cuts off the segment R_c^2 (t - sin t) / 2, t = 2 asin(L /
   * 2 R_c), which sweeps at most 2 pi r_max times its area.
   */
  double
  chord_deficit_bound(const dealii::Triangulation<2> &tria)
  {
    double bound = 0.0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == fem::upper_punch)
          {
            const auto   a = face->vertex(0), b = face->vertex(1);
            const double L = a.distance(b);
            const double t = 2.0 * std::asin(L / (2.0 * cup_radius));
            bound += 2.0 * pi * std::max(a[0], b[0]) * 0.5 * cup_radius
                     * cup_radius * (t - std::sin(t));
          }
    return bound;
  }

  /// pi R^2 H plus the spherical cap of height h_c on a sphere of radius
  /// R_c: pi h^2 (3 R_c - h) / 3.
  double
  cylinder_and_cap(const double R, const double height)
  {
    return pi * R * R * height
           + pi * cup_depth * cup_depth * (3.0 * cup_radius - cup_depth) / 3.0;
  }
} // namespace

TEST(TabletConcavePunch, ShippedMeshIsTheCylinderPlusTheSphericalCap)
{
  fem::TabletGeometry      g = shipped_mesh();
  dealii::Triangulation<2> tria;
  fem::read_compact_mesh(tria, g);
  EXPECT_NEAR(g.die_diameter, D, 1e-15);
  EXPECT_NEAR(g.fill_height, H, 1e-15);

  // The top of the compact on the axis is the bottom of the cup.
  double top = 0.0;
  for (const auto &cell : tria.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      top = std::max(top, cell->vertex(v)[1]);
  EXPECT_NEAR(top, H + cup_depth, 1e-12);

  // Chords of the cup arc lie inside the powder: the mesh misses at most
  // the segments between arc and chords.
  const double exact = cylinder_and_cap(0.5 * D, H);
  const double V     = volume_of_revolution(tria);
  const double bound = chord_deficit_bound(tria);
  EXPECT_LE(V, exact * (1.0 + 1e-13));
  EXPECT_GE(V, exact - bound);
  EXPECT_LT(bound, 2e-4 * exact);

  // Refinement follows the cup sphere, so the chord deficit shrinks.
  tria.refine_global(2);
  const double V_fine = volume_of_revolution(tria);
  EXPECT_GE(V_fine, exact - chord_deficit_bound(tria));
  EXPECT_LE(V_fine, exact * (1.0 + 1e-13));
  EXPECT_LT(exact - V_fine, 0.1 * (exact - V));
}

TEST(TabletConcavePunch, BuiltInCupMeshHasTheSameVolume)
{
  fem::TabletGeometry g;
  g.die_diameter           = D;
  g.fill_height            = H;
  g.n_radial_cells         = 16;
  g.upper_punch.cup_depth  = cup_depth;
  g.upper_punch.cup_radius = cup_radius;
  dealii::Triangulation<2> tria;
  fem::make_compact(tria, g, 1);
  const double exact = cylinder_and_cap(0.5 * D, H);
  const double V     = volume_of_revolution(tria);
  // The stretched columns put every top vertex on the profile; the cells
  // that straddle the cup edge cut its corner, the others lie under the
  // arc.
  EXPECT_LE(V, exact * (1.0 + 1e-13));
  EXPECT_NEAR(V / exact, 1.0, 1e-4);
}

TEST(TabletConcavePunch, UnusableMeshFilesAreRejectedWithTheReason)
{
  const auto expect_message
    = [](fem::TabletGeometry g, const std::string &fragment) {
        dealii::Triangulation<2> tria;
        try
          {
            fem::read_compact_mesh(tria, g);
            ADD_FAILURE() << "accepted " << g.mesh_file;
          }
        catch (const std::runtime_error &e)
          {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
              << e.what();
          }
      };

  fem::TabletGeometry missing;
  missing.mesh_file = "no_such_mesh.msh";
  expect_message(missing, "no_such_mesh.msh");

  // The concave mesh with a flat punch declared.
  fem::TabletGeometry flat = shipped_mesh();
  flat.upper_punch         = fem::PunchProfile();
  expect_message(flat, "does not follow the punch profile");

  // A rectangle whose top edge has no physical id (so deal.II gives it 0,
  // the axis): no upper punch face.
  const auto folder = std::filesystem::temp_directory_path()
                      / ("compax-concave-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  fem::TabletGeometry no_punch;
  no_punch.mesh_file = (folder / "no_punch.msh").string();
  std::ofstream(no_punch.mesh_file) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                       "$Nodes\n4\n1 0 0 0\n2 0.005 0 0\n"
                                       "3 0.005 0.007 0\n4 0 0.007 0\n"
                                       "$EndNodes\n$Elements\n4\n"
                                       "1 1 2 2 1 1 2\n2 1 2 1 2 2 3\n"
                                       "3 1 2 0 4 4 1\n"
                                       "4 3 2 10 1 1 2 3 4\n$EndElements\n";
  expect_message(no_punch, "no boundary face has id 3 (upper punch)");

  fem::TabletGeometry garbage;
  garbage.mesh_file = (folder / "garbage.msh").string();
  std::ofstream(garbage.mesh_file) << "not a mesh\n";
  expect_message(garbage, "garbage.msh");
  std::filesystem::remove_all(folder);
}

namespace
{
  constexpr double E = 2.0e9, nu = 0.3;

  fem::TabletSolverSettings
  frictionless_die()
  {
    fem::TabletSolverSettings s;
    s.wall_friction            = 0.0;
    s.initial_relative_density = 0.8;
    // Penetrations (pressure / penalty ~ 1e-6 of the strokes) stay far
    // below the tolerances of the checks.
    s.penalty_factor = 1e5;
    return s;
  }

  std::shared_ptr<const fem::MaterialModel>
  elastic()
  {
    return std::make_shared<fem::LinearElasticMaterial>(E, nu);
  }
} // namespace

TEST(TabletConcavePunch, ElasticCompactIsInAxialEquilibrium)
{
  fem::TabletSolverSettings s = frictionless_die();
  s.geometry                  = shipped_mesh();
  fem::TabletSolver<2> solver(s, elastic(), MPI_COMM_WORLD);
  EXPECT_NEAR(solver.geometry().fill_height, H, 1e-15);
  EXPECT_NEAR(solver.volume() / cylinder_and_cap(0.5 * D, H), 1.0, 2e-4);
  EXPECT_NEAR(solver.mean_relative_density(), 0.8, 1e-14);
  // Strokes well beyond the sag of the cup's chords (about 1.2 um between
  // the vertices of the shipped mesh).
  for (const double stroke : {20e-6, 60e-6})
    {
      ASSERT_TRUE(solver.advance(H - stroke, 0.0));
      const auto &f = solver.forces();
      EXPECT_GT(f.upper_punch_force, 0.0);
      // The frictionless die wall pushes radially only.
      EXPECT_NEAR(f.lower_punch_force / f.upper_punch_force, 1.0, 1e-7);
      EXPECT_NEAR(f.die_wall_friction_force, 0.0, 1e-12);
    }
}

TEST(TabletConcavePunch, VanishingCupGivesTheFlatFacedResult)
{
  const double       R = 0.5 * D, delta = 1e-3 * H;
  const unsigned int n_radial = 6;
  // The flat punch: uniaxial strain, F = (lambda + 2 mu) (delta / H) pi R^2,
  // less the penalty penetrations of the punches (about 4e-6 of delta).
  const double flat
    = (fem::lame_lambda(E, nu) + 2.0 * fem::shear_modulus(E, nu)) * delta / H
      * pi * R * R;
  double F_flat = 0.0;
  for (const double h : {0.0, 1e-8, 1e-9, 1e-10})
    {
      fem::TabletSolverSettings s = frictionless_die();
      s.geometry.die_diameter     = D;
      s.geometry.fill_height      = H;
      s.geometry.n_radial_cells   = n_radial;
      // A full-face cup of depth h (a = R).
      s.geometry.upper_punch.cup_depth = h;
      s.geometry.upper_punch.cup_radius
        = h > 0.0 ? (R * R + h * h) / (2.0 * h) : 0.0;
      fem::TabletSolver<2> solver(s, elastic(), MPI_COMM_WORLD);
      ASSERT_TRUE(solver.advance(H - delta, 0.0));
      const auto &f = solver.forces();
      EXPECT_NEAR(f.lower_punch_force / f.upper_punch_force, 1.0, 1e-7);
      if (h == 0.0)
        {
          F_flat = f.upper_punch_force;
          EXPECT_NEAR(F_flat / flat, 1.0, 1e-5);
          continue;
        }
      // The cup lengthens the column by c(r) ~ h (1 - r^2/R^2), which
      // lowers the mean strain by about h / (2 H); and the faces are
      // chords of the cup, which the punch meets up to their sag
      // L^2 / (8 R_c) later. Both vanish with h.
      const double L     = R / n_radial;
      const double sag   = L * L / (8.0 * s.geometry.upper_punch.cup_radius);
      const double bound = h / (2.0 * H) + sag / delta;
      EXPECT_LE(std::abs(f.upper_punch_force / F_flat - 1.0), bound + 1e-8)
        << "cup depth " << h;
    }
}

TEST(TabletConcavePunch, TabletIsThickerOnTheAxisByTheCupDepth)
{
  fem::TabletSolverSettings s = frictionless_die();
  s.geometry                  = shipped_mesh();
  fem::TabletSolver<2> solver(s, elastic(), MPI_COMM_WORLD);
  // 3 % axial strain in 6 steps.
  for (int k = 1; k <= 6; ++k)
    ASSERT_TRUE(solver.advance(H - k * 0.035e-3, 0.0));
  const auto top    = solver.boundary_positions(fem::upper_punch);
  const auto bottom = solver.boundary_positions(fem::lower_punch);
  ASSERT_FALSE(top.empty());
  const auto at
    = [](const std::vector<dealii::Point<2>> &points, const double r) {
        const auto nearest
          = std::min_element(points.begin(),
                             points.end(),
                             [r](const auto &a, const auto &b) {
                               return std::abs(a[0] - r) < std::abs(b[0] - r);
                             });
        return *nearest;
      };
  const double axis_thickness = at(top, 0.0)[1] - at(bottom, 0.0)[1];
  const double rim_thickness  = at(top, 0.5 * D)[1] - at(bottom, 0.5 * D)[1];
  // The punch touches the faces at their quadrature points, and the faces
  // are chords of the cup: a vertex may stand off the cup by up to the
  // sag L^2 / (8 R_c) of its chords (about 1.2 um on the shipped mesh).
  double longest = 0.0;
  for (std::size_t k = 0; k + 1 < top.size(); k += 2)
    longest = std::max(longest, top[k].distance(top[k + 1]));
  const double sag = longest * longest / (8.0 * cup_radius);
  EXPECT_LT(sag, 2e-3 * cup_depth);
  EXPECT_NEAR(at(top, 0.5 * D)[1], H - 6 * 0.035e-3, sag);
  EXPECT_NEAR(axis_thickness - rim_thickness, cup_depth, sag);
}

namespace
{
  /// Largest sag d^2 / (8 R_c) below the cup of the upper punch faces of
  /// @p solver, d the longest distance between two vertices of a face (a
  /// face touches the punch at its quadrature points, inside its vertices).
  template <int dim>
  double
  largest_sag(const fem::TabletSolver<dim> &solver)
  {
    const auto         points = solver.boundary_positions(fem::upper_punch);
    const unsigned int n      = dim == 2 ? 2 : 4;
    double             d      = 0.0;
    for (std::size_t f = 0; f + n <= points.size(); f += n)
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = i + 1; j < n; ++j)
          d = std::max(d, points[f + i].distance(points[f + j]));
    return d * d / (8.0 * cup_radius);
  }
} // namespace

TEST(TabletConcavePunch, QuarterModelAgreesWithAxisymmetricModel)
{
  // The built-in meshes with the shipped cup, frictionless elastic, 4 %
  // axial strain at the die wall in 3 steps.
  fem::TabletSolverSettings s = frictionless_die();
  s.penalty_factor            = 1e4;
  s.geometry.die_diameter     = D;
  s.geometry.fill_height      = H;
  s.geometry.n_radial_cells   = 8;
  s.geometry.upper_punch      = shipped_mesh().upper_punch;
  const double         stroke = 300e-6;
  fem::TabletSolver<2> rz(s, elastic(), MPI_COMM_WORLD);
  const double         sag2 = largest_sag(rz);
  for (int k = 1; k <= 3; ++k)
    ASSERT_TRUE(rz.advance(H - k * stroke / 3, 0.0));
  s.refinements = 2;
  fem::TabletSolver<3> quarter(s, elastic(), MPI_COMM_WORLD);
  const double         sag3 = largest_sag(quarter);
  for (int k = 1; k <= 3; ++k)
    ASSERT_TRUE(quarter.advance(H - k * stroke / 3, 0.0));
  const auto &f2 = rz.forces(), &f3 = quarter.forces();
  EXPECT_NEAR(f3.lower_punch_force / f3.upper_punch_force, 1.0, 1e-6);
  EXPECT_NEAR(f2.lower_punch_force / f2.upper_punch_force, 1.0, 1e-6);
  // The faceted 3-D die (8 facets per quarter circle) has a cross-section
  // 0.6 % below the circle's; the faces of either mesh meet the cup up to
  // their sag later, which shortens the effective stroke.
  const double tolerance = 0.006 + (sag2 + sag3) / stroke;
  EXPECT_LT(tolerance, 0.05);
  EXPECT_NEAR(f3.upper_punch_force / f2.upper_punch_force, 1.0, tolerance)
    << "sags " << sag2 << " and " << sag3 << " m";
  std::cout << "cup, r-z: upper " << f2.upper_punch_force
            << " N; 3-D quarter x 4: upper " << f3.upper_punch_force
            << " N; tolerance " << tolerance << '\n';
}
