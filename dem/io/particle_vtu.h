#pragma once

#include "dem/solver/bed.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace compax::dem
{
  /**
   * The point data of a particle snapshot gathered contact by contact
   * (coordination, net force, mean contact force, intact bonds, and the
   * largest value among its contacts of every internal variable the
   * contact laws declare), written as a VTK XML unstructured grid of vertices.
   * Any contact set feeds it (die beds, periodic cells), each with its own
   * branch vectors.
   */
  class ParticleSnapshot
  {
  public:
    explicit ParticleSnapshot(const ParticleSystem &particles);

    /// A contact between i and j with unit normal n (from j to i), normal
    /// force P (positive repulsive), law and internal variables.
    void
    add_contact(std::uint32_t          i,
                std::uint32_t          j,
                const Eigen::Vector3d &n,
                double                 force,
                const ParticleLaw     &law,
                const ContactHistory  &history);

    /// Positions written (e.g. wrapped into a periodic cell first).
    std::vector<Eigen::Vector3d> &
    positions()
    {
      return points;
    }

    void
    write(const std::filesystem::path &file) const;

  private:
    std::vector<Eigen::Vector3d> points;
    std::vector<double>          radii;
    std::vector<int>             material, coordination, bonds;
    std::vector<double>          force_sum;
    std::vector<Eigen::Vector3d> net;
    /// The name of each declared internal variable met so far (a law's
    /// static string) and its per-particle largest value, written as
    /// "max_<name>".
    std::vector<std::pair<const char *, std::vector<double>>> largest_history;
  };

  /**
   * Writes the particles of a bed as a VTK XML unstructured grid of vertices
   * (.vtu), for ParaView: glyph them with spheres scaled by "radius". Point
   * data: radius [m], material, coordination (number of loaded particle
   * contacts), net contact force magnitude on the particle [N], number of
   * intact solid bridges, the mean normal force of its contacts [N], and
   * max_<name>, the largest value among its contacts of each internal
   * variable its contacts' laws declare (max_plastic_radius [m] and
   * max_bond_radius [m] for the bonded law).
   */
  void
  write_particles_vtu(const std::filesystem::path &file, const Bed &bed);

  /**
   * A ParaView collection (.pvd) of snapshots; each entry is (time-like
   * value, file name relative to the .pvd). Rewritten whole on each call so
   * an interrupted run leaves a valid file.
   */
  void
  write_pvd(const std::filesystem::path                       &file,
            const std::vector<std::pair<double, std::string>> &snapshots);
} // namespace compax::dem
