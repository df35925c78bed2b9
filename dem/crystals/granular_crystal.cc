#include "dem/crystals/granular_crystal.h"

#include "dem/numbers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    struct NamedConfiguration
    {
      CrystalConfiguration configuration;
      const char          *name;
    };

    constexpr NamedConfiguration names[]
      = {{CrystalConfiguration::chain_1d, "chain-1d"},
         {CrystalConfiguration::square_2d, "square-2d"},
         {CrystalConfiguration::cubic_3d, "cubic-3d"},
         {CrystalConfiguration::square_2d_rotated, "square-2d-rotated"},
         {CrystalConfiguration::hexagonal_2d, "hexagonal-2d"},
         {CrystalConfiguration::square_2d_preloaded, "square-2d-preloaded"},
         {CrystalConfiguration::bcc_hydrostatic, "bcc-hydrostatic"},
         {CrystalConfiguration::bcc_die, "bcc-die"}};
  } // namespace

  const std::vector<CrystalConfiguration> &
  all_crystal_configurations()
  {
    static const std::vector<CrystalConfiguration> all = [] {
      std::vector<CrystalConfiguration> list;
      for (const auto &n : names)
        list.push_back(n.configuration);
      return list;
    }();
    return all;
  }

  std::string
  crystal_configuration_name(const CrystalConfiguration configuration)
  {
    for (const auto &n : names)
      if (n.configuration == configuration)
        return n.name;
    throw std::invalid_argument("unknown crystal configuration");
  }

  CrystalConfiguration
  crystal_configuration_from_name(const std::string &name)
  {
    for (const auto &n : names)
      if (name == n.name)
        return n.configuration;
    throw std::invalid_argument("unknown crystal configuration '" + name + "'");
  }

  std::string
  crystal_configuration_names(const std::string &separator)
  {
    std::string list;
    for (const auto &n : names)
      list += (list.empty() ? "" : separator) + std::string(n.name);
    return list;
  }

  bool
  CrystalLattice::spans(const unsigned int axis) const
  {
    switch (dimension)
      {
        case 1:
          return axis == 2;
        case 2:
          return axis != 1;
        default:
          return true;
      }
  }

  std::vector<Eigen::Vector3d>
  CrystalLattice::lattice_vectors(const double range) const
  {
    // Every primitive vector is at least 2R long and the lattices are not
    // very oblique, so coefficients up to range / R + 1 cover the ball.
    const int n  = static_cast<int>(std::ceil(range / radius)) + 1;
    const int n1 = n, n2 = dimension >= 2 ? n : 0, n3 = dimension >= 3 ? n : 0;
    std::vector<Eigen::Vector3d> vectors;
    for (int i = -n1; i <= n1; ++i)
      for (int j = -n2; j <= n2; ++j)
        for (int k = -n3; k <= n3; ++k)
          {
            if (i == 0 && j == 0 && k == 0)
              continue;
            Eigen::Vector3d d = i * primitive[0];
            if (dimension >= 2)
              d += j * primitive[1];
            if (dimension >= 3)
              d += k * primitive[2];
            if (d.norm() <= range)
              vectors.push_back(d);
          }
    std::stable_sort(vectors.begin(),
                     vectors.end(),
                     [](const Eigen::Vector3d &a, const Eigen::Vector3d &b) {
                       return a.norm() < b.norm();
                     });
    return vectors;
  }

  double
  CrystalLattice::measure_per_particle(const Eigen::Vector3d &strains) const
  {
    double measure = 1.0;
    for (unsigned int axis = 0; axis < 3; ++axis)
      if (spans(axis))
        measure *= cell_size[axis] * (1.0 - strains[axis]);
    return measure / particles_per_cell;
  }

  double
  CrystalLattice::relative_density(const Eigen::Vector3d &strains) const
  {
    const double R        = radius;
    const double particle = dimension == 3
                              ? 4.0 / 3.0 * pi * R * R * R
                              : (dimension == 2 ? pi * R * R : 2.0 * R);
    return particle / measure_per_particle(strains);
  }

  CrystalLattice
  make_crystal_lattice(const CrystalConfiguration configuration, const double R)
  {
    CrystalLattice lattice;
    lattice.radius    = R;
    lattice.primitive = {Eigen::Vector3d::Zero(),
                         Eigen::Vector3d::Zero(),
                         Eigen::Vector3d::Zero()};
    lattice.cell_size = Eigen::Vector3d::Ones();
    const double d    = 2.0 * R;
    switch (configuration)
      {
        case CrystalConfiguration::chain_1d:
          lattice.dimension    = 1;
          lattice.primitive[0] = {0.0, 0.0, d};
          lattice.cell_size[2] = d;
          break;
        case CrystalConfiguration::square_2d:
        case CrystalConfiguration::square_2d_preloaded:
          lattice.dimension    = 2;
          lattice.primitive[0] = {d, 0.0, 0.0};
          lattice.primitive[1] = {0.0, 0.0, d};
          lattice.cell_size    = {d, 1.0, d};
          break;
        case CrystalConfiguration::cubic_3d:
          lattice.dimension    = 3;
          lattice.primitive[0] = {d, 0.0, 0.0};
          lattice.primitive[1] = {0.0, d, 0.0};
          lattice.primitive[2] = {0.0, 0.0, d};
          lattice.cell_size    = {d, d, d};
          break;
        case CrystalConfiguration::square_2d_rotated:
          {
            // Neighbours along (1, +-1)/sqrt(2); layers sqrt(2) R apart,
            // the conventional cell (2 sqrt(2) R)^2 holds two particles.
            const double h             = std::sqrt(2.0) * R;
            lattice.dimension          = 2;
            lattice.primitive[0]       = {h, 0.0, h};
            lattice.primitive[1]       = {h, 0.0, -h};
            lattice.cell_size          = {2.0 * h, 1.0, 2.0 * h};
            lattice.particles_per_cell = 2;
            break;
          }
        case CrystalConfiguration::hexagonal_2d:
          {
            // Horizontal rows of touching spheres, rows sqrt(3) R apart;
            // the conventional cell 2R x 2 sqrt(3) R holds two particles.
            const double h             = std::sqrt(3.0) * R;
            lattice.dimension          = 2;
            lattice.primitive[0]       = {d, 0.0, 0.0};
            lattice.primitive[1]       = {R, 0.0, h};
            lattice.cell_size          = {d, 1.0, 2.0 * h};
            lattice.particles_per_cell = 2;
            break;
          }
        case CrystalConfiguration::bcc_hydrostatic:
        case CrystalConfiguration::bcc_die:
          {
            // Cube edge a = 4R / sqrt(3): the neighbours along <111> touch.
            const double a             = 4.0 * R / std::sqrt(3.0);
            lattice.dimension          = 3;
            lattice.primitive[0]       = 0.5 * a * Eigen::Vector3d(1, 1, -1);
            lattice.primitive[1]       = 0.5 * a * Eigen::Vector3d(1, -1, 1);
            lattice.primitive[2]       = 0.5 * a * Eigen::Vector3d(-1, 1, 1);
            lattice.cell_size          = {a, a, a};
            lattice.particles_per_cell = 2;
            break;
          }
      }
    return lattice;
  }

  Eigen::Vector3d
  crystal_cell_strains(const CrystalConfiguration configuration,
                       const double               epsilon,
                       const double               preload)
  {
    switch (configuration)
      {
        case CrystalConfiguration::square_2d_preloaded:
          return {preload, 0.0, preload + epsilon};
        case CrystalConfiguration::bcc_hydrostatic:
          return {epsilon, epsilon, epsilon};
        default:
          return {0.0, 0.0, epsilon};
      }
  }

  bool
  crystal_uses_relative_density(const CrystalConfiguration configuration)
  {
    return configuration == CrystalConfiguration::bcc_hydrostatic
           || configuration == CrystalConfiguration::bcc_die;
  }

  double
  crystal_strain_at_density(const CrystalConfiguration configuration,
                            const double               rho,
                            const double               preload)
  {
    const CrystalLattice lattice = make_crystal_lattice(configuration, 1.0);
    const double         start   = lattice.relative_density(
      crystal_cell_strains(configuration, 0.0, preload));
    if (rho < start)
      return -1.0;
    // rho / rho(0) = product of (1 - eps_i(0)) / (1 - eps_i(epsilon)) over
    // the axes that move with epsilon.
    const double ratio = start / rho;
    switch (configuration)
      {
        case CrystalConfiguration::bcc_hydrostatic:
          return 1.0 - std::cbrt(ratio);
        case CrystalConfiguration::square_2d_preloaded:
          return (1.0 - preload) * (1.0 - ratio);
        default:
          return 1.0 - ratio;
      }
  }
} // namespace compax::dem
