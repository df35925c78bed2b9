#pragma once

#include "dem/packing/random_source.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace compax::dem
{
  /// What to insert: a box, the packing density to grow to, the radii.
  struct InsertionSpec
  {
    /// Edge lengths of the box [m] (x, y periodic; z between plates).
    Eigen::Vector3d box{1e-3, 1e-3, 1e-3};
    /// Solid fraction sum(V_i) / V_box reached at full size [-].
    double packing_density = 0.59;
    /// Radii at full size.
    SizeDistribution sizes;
    /// If nonzero: insert this many particles and scale the box (keeping
    /// its aspect ratio) to the packing density instead of filling it.
    std::size_t particle_count = 0;
    /// Radii at insertion are this fraction of the full radii [-].
    double initial_scale = 0.5;
  };

  /// Particles inserted at random, not yet grown.
  struct InsertedParticles
  {
    /// The box actually used [m] (scaled if particle_count was given).
    Eigen::Vector3d box;
    /// Centres [m], x, y in [0, L), z in [r, L_z - r] at the initial scale.
    std::vector<Eigen::Vector3d> positions;
    /// Radii at full size [m], sorted from large to small.
    std::vector<double> radii;
  };

  /**
   * Draws full-size radii until their volume reaches packing_density times
   * the box (or particle_count of them), then places the spheres, shrunk by
   * initial_scale, one by one at uniformly random positions in the box
   * periodic in x and y, retrying a position up to 1000 times to avoid
   * overlaps (minimum image in x, y; inside the plates in z). Larger
   * spheres go first. Growing them to full size is the dynamics' job.
   * Reproducible: the same spec and seed give the same particles.
   */
  InsertedParticles
  insert_random(const InsertionSpec &spec, RandomSource &random);
} // namespace compax::dem
