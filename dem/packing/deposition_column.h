#pragma once

#include "dem/packing/deposition_grid.h"
#include "dem/packing/random_source.h"
#include "dem/particles/particle_system.h"

namespace compax::dem
{
  /// The lateral boundary the spheres fall between.
  enum class DepositionContainer
  {
    /// A rigid cylindrical die of diameter die_diameter, axis z through the
    /// origin.
    cylinder,
    /// A square column [-L/2, L/2)^2 of side L = die_diameter, periodic in
    /// x and y (no lateral wall: the lateral faces of a periodic cell).
    periodic_square,
    /// A rigid die of square cross-section [-L/2, L/2]^2, L = die_diameter.
    square
  };

  /**
   * The spheres deposited so far in a container with its floor at z = 0,
   * and the ballistic drop of one more (Jullien & Meakin 1989), shared by
   * every deposition so that all of them settle spheres the same way: a
   * sphere falls until it touches the floor or a sphere already placed,
   * then rolls down over its supports by projected descent (move down by
   * h, project out of every overlap with spheres, floor and walls, accept
   * if it went down, halve h otherwise) until h < 1e-6 R. A periodic
   * column wraps around in x and y instead of stopping at a wall.
   */
  class DepositionColumn
  {
  public:
    /// An empty container of diameter or side @p width for spheres of
    /// radius at most @p largest_radius.
    DepositionColumn(DepositionContainer container,
                     double              width,
                     double              largest_radius);

    /// A uniformly random drop position of a sphere of radius @p R in the
    /// cross-section (inside the walls), at the height R of the floor.
    Eigen::Vector3d
    random_start(RandomSource &random, double R) const;

    /// Drops a sphere of radius @p R from the lateral position of @p start
    /// and adds it, of @p material, where it comes to rest.
    void
    drop(const Eigen::Vector3d &start, double R, unsigned int material);

    /// The spheres in the order they were dropped.
    ParticleSystem particles;

  private:
    /// x - y, in a periodic column reduced to the shortest image in x and
    /// y: the offset of a centre x from a centre y. (The container's kind
    /// is a template argument of the loops over neighbours, decided once.)
    template <bool periodic>
    Eigen::Vector3d
    offset(const Eigen::Vector3d &x, const Eigen::Vector3d &y) const;

    /// Moves q inside the walls; whether it had to move (a periodic wrap
    /// is no move).
    bool
    confine(Eigen::Vector3d &q, double R) const;

    /// Projects a trial centre of a sphere of radius R out of every
    /// overlap; false if it does not get free in 200 sweeps.
    template <bool periodic>
    bool
    project(Eigen::Vector3d &q, double R) const;

    DepositionContainer container;
    double              width;
    DepositionGrid      grid;
  };
} // namespace compax::dem
