#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

/**
 * @file
 * Geometry of the granular crystals of Gonzalez & Cuitino 2012, Sec. 4.1
 * (Figs. 9, 11-13, 15): Bravais lattices of identical touching spheres of
 * radius R, compressed under displacement control along z. A 1-D chain
 * lies on the z axis, the 2-D lattices in the x-z plane, the 3-D lattices
 * fill space. The cell deformation is the diagonal stretch
 * diag(1 - eps_x, 1 - eps_y, 1 - eps_z), compressive strains positive.
 *
 * Every configuration is a Bravais lattice (one particle per primitive
 * cell), so every particle is a centre of inversion: under an affine cell
 * deformation the contact forces on a particle cancel in pairs (+d, -d) and
 * the affine configuration is in equilibrium without solving for particle
 * positions (frictionless central forces, no rotations).
 */

namespace compax::dem
{
  /// The crystals and loadings of Sec. 4.1.
  enum class CrystalConfiguration
  {
    /// 1-D chain along the load (Fig. 9a); equivalent to a chain of any
    /// length between rigid frictionless plates.
    chain_1d,
    /// Square lattice, periodic in x, loaded along z (Fig. 9b).
    square_2d,
    /// Simple cubic lattice, periodic in x and y, loaded along z (Fig. 9c).
    cubic_3d,
    /// Square lattice rotated by pi/4, periodic in x (Fig. 11).
    square_2d_rotated,
    /// Close-packed (hexagonal) layer with horizontal rows, periodic in x
    /// (Fig. 12).
    hexagonal_2d,
    /// Square lattice first confined by eps0 in x and z, then loaded
    /// along z with x held (Fig. 13).
    square_2d_preloaded,
    /// Body-centred cubic, eps_x = eps_y = eps_z (Fig. 15, Fig. 16).
    bcc_hydrostatic,
    /// Body-centred cubic, eps_x = eps_y = 0 (Fig. 15, Fig. 17).
    bcc_die
  };

  /// All configurations, in the order of the paper.
  const std::vector<CrystalConfiguration> &
  all_crystal_configurations();

  /// The name used on the command line and in output files, e.g.
  /// "bcc-die".
  std::string
  crystal_configuration_name(CrystalConfiguration configuration);

  /// Inverse of crystal_configuration_name(); throws std::invalid_argument
  /// for an unknown name.
  CrystalConfiguration
  crystal_configuration_from_name(const std::string &name);

  /// "chain-1d|square-2d|..." for a selection pattern.
  std::string
  crystal_configuration_names(const std::string &separator);

  /**
   * A Bravais lattice of spheres of radius R with nearest neighbours
   * touching (distance 2R), and the orthogonal conventional cell through
   * whose faces loads and lateral reactions are reported.
   */
  struct CrystalLattice
  {
    /// 1 (along z), 2 (x-z plane) or 3.
    unsigned int dimension = 3;
    /// Primitive vectors; only the first `dimension` are used [m].
    std::array<Eigen::Vector3d, 3> primitive;
    /// Undeformed edges of the conventional orthogonal cell along x, y, z
    /// [m]; 1 along axes outside the lattice.
    Eigen::Vector3d cell_size;
    /// Particles in the conventional cell.
    unsigned int particles_per_cell = 1;
    /// Sphere radius R [m].
    double radius = 0.0;

    /// Whether axis (0 = x, 1 = y, 2 = z) lies in the lattice.
    bool
    spans(unsigned int axis) const;

    /// Undeformed lattice vectors (particle 0 excluded) no longer than
    /// `range` [m], sorted by length.
    std::vector<Eigen::Vector3d>
    lattice_vectors(double range) const;

    /**
     * Relative density of the deformed cell (strains eps_x, eps_y, eps_z):
     * sphere volume over cell volume in 3-D (Eq. 19 for the BCC crystal),
     * area fraction of the spheres' equatorial discs in the lattice plane
     * in 2-D, length fraction 2R / spacing in 1-D. Volumes of the
     * overlapping caps are not subtracted, as in Eq. (19), so it exceeds 1
     * at large compaction.
     */
    double
    relative_density(const Eigen::Vector3d &strains) const;

    /// Volume (3-D), area (2-D) or length (1-D) per particle of the
    /// deformed lattice.
    double
    measure_per_particle(const Eigen::Vector3d &strains) const;
  };

  /// The lattice of a configuration, spheres of radius R [m].
  CrystalLattice
  make_crystal_lattice(CrystalConfiguration configuration, double R);

  /**
   * Cell strains (eps_x, eps_y, eps_z) of the displacement-controlled path
   * at load-axis deformation epsilon. For every configuration epsilon is
   * the change of the layer spacing along z over the undeformed spacing,
   * i.e. gamma / 2R (1-D, square, cubic), gamma / (sqrt(2) R) (rotated) and
   * gamma / (sqrt(3) R) (close-packed) as in Sec. 4.1, and for the
   * preloaded square lattice gamma / 2R measured from the confined state:
   * eps_z = eps0 + epsilon, eps_x = eps0. Hydrostatic BCC: all three equal
   * epsilon; die BCC: eps_z = epsilon only.
   */
  Eigen::Vector3d
  crystal_cell_strains(CrystalConfiguration configuration,
                       double               epsilon,
                       double               preload);

  /// Whether the paper plots the configuration against relative density
  /// (the BCC crystals) rather than deformation.
  bool
  crystal_uses_relative_density(CrystalConfiguration configuration);

  /**
   * Load-axis deformation epsilon at which the configuration reaches
   * relative density rho (inverse of relative_density() along the path).
   * Returns a negative value when rho is below the undeformed density.
   */
  double
  crystal_strain_at_density(CrystalConfiguration configuration,
                            double               rho,
                            double               preload);
} // namespace compax::dem
