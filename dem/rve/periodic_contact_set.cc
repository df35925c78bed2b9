#include "dem/rve/periodic_contact_set.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace compax::dem
{
  namespace
  {
    /// Spectral norm of a 3x3 matrix.
    double
    spectral_norm(const Eigen::Matrix3d &A)
    {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(
        A.transpose() * A, Eigen::EigenvaluesOnly);
      return std::sqrt(std::max(eig.eigenvalues().maxCoeff(), 0.0));
    }
  } // namespace

  bool
  PeriodicContactSet::moved_too_far(const ParticleSystem &particles,
                                    const PeriodicCell   &cell) const
  {
    // Displacements relative to the affine motion of the cell since the
    // build, and the cell's own change acting on a candidate branch.
    const Eigen::Matrix3d A = cell.lattice() * reference_lattice.inverse();
    const std::vector<Eigen::Vector3d> &x0     = built_positions();
    double                              max_sq = 0.0;
    for (std::size_t i = 0; i < particles.size(); ++i)
      max_sq
        = std::max(max_sq, (particles.positions[i] - A * x0[i]).squaredNorm());
    const double branch = 2.0 * particles.max_radius() + skin();
    return 2.0 * std::sqrt(max_sq)
             + spectral_norm(A - Eigen::Matrix3d::Identity()) * branch
           >= skin();
  }

  void
  PeriodicContactSet::find_contacts(const ParticleSystem &particles,
                                    const PeriodicCell   &cell,
                                    const ContactModel   &model)
  {
    const double needed_width = 2.0 * particles.max_radius() + skin();
    for (int axis = 0; axis < 3; ++axis)
      if (cell.width(axis) < needed_width)
        throw std::runtime_error(
          "periodic cell: width " + std::to_string(cell.width(axis))
          + " m along lattice direction " + std::to_string(axis)
          + " is below the largest diameter plus the skin ("
          + std::to_string(needed_width)
          + " m); use more particles or a larger cell");
    grid.find_pairs(
      cell, particles.positions, particles.radii, skin(), candidates);
    merge_candidates(
      candidates,
      pairs,
      old_pairs,
      [](const PeriodicContact &c) {
        return ImagePair{c.i, c.j, c.image};
      },
      [&](const ImagePair &ij) {
        return PeriodicContact{ij.i,
                               ij.j,
                               ij.image,
                               model.pair_law(particles.materials[ij.i],
                                              particles.radii[ij.i],
                                              particles.materials[ij.j],
                                              particles.radii[ij.j]),
                               ContactHistory{}};
      });
    reference_lattice = cell.lattice();
  }
} // namespace compax::dem
