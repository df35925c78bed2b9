#pragma once

#include "dem/crystals/crystal_contacts.h"
#include "dem/crystals/granular_crystal.h"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <vector>

/**
 * @file
 * Displacement-controlled compression of a granular crystal (Gonzalez &
 * Cuitino 2012, Sec. 4.1): the response along the path of a configuration
 * and the deformations at which successive families of contacts form.
 */

namespace compax::dem
{
  /// Settings of compute_crystal_path().
  struct CrystalPathOptions
  {
    /// Final load-axis deformation epsilon (see crystal_cell_strains()).
    double max_strain = 0.1;
    /// Equal increments of epsilon from 0 to max_strain.
    unsigned int steps = 200;
    /// Confinement eps0 of the preloaded square lattice.
    double preload = 0.04;
    /// Contact solver settings; the neighbour range is widened so that
    /// every lattice vector left out stays 0.25 R beyond contact at
    /// max_strain.
    CrystalContactOptions contact;
  };

  /// One point of the path.
  struct CrystalPathPoint
  {
    /// Load-axis deformation epsilon.
    double strain = 0.0;
    /// (eps_x, eps_y, eps_z).
    Eigen::Vector3d cell_strains = Eigen::Vector3d::Zero();
    CrystalResponse response;
  };

  /**
   * Formation of a family of contacts: the neighbours of a particle that
   * start carrying force at the same deformation (refined by bisection to
   * ~1e-12 in epsilon). Neighbours already loaded at epsilon = 0 (the
   * preloaded lattice) form at 0.
   */
  struct ContactFormation
  {
    /// Load-axis deformation epsilon at formation.
    double strain = 0.0;
    /// Relative density there.
    double relative_density = 0.0;
    /// Neighbours of one particle that form contact.
    unsigned int contacts = 0;
    /// Their shortest undeformed distance, in diameters 2R.
    double distance = 0.0;
  };

  /// Result of compute_crystal_path().
  struct CrystalPath
  {
    /// Solved points: the grid from epsilon = 0 to max_strain or, when the
    /// nonlocal formulation reaches a limit point, the grid up to it and a
    /// last point just below it.
    std::vector<CrystalPathPoint> points;
    /// Contact formations in order of deformation: [0] the first contacts,
    /// [1] the second, [2] the third, ...
    std::vector<ContactFormation> formations;
    /**
     * Limit point of the nonlocal formulation: the smallest deformation
     * found without a solution (Algorithm 1 diverges because the
     * nonlocal terms grow faster than the Hertz overlaps can follow; the
     * iteration matrix reaches spectral radius 1). Bracketed to 1e-5 of a
     * step above the last point. NaN when the whole path was solved.
     */
    double failure_strain = std::numeric_limits<double>::quiet_NaN();

    bool
    complete() const
    {
      return std::isnan(failure_strain);
    }

    /// Relative density at which the k-th contacts form (k = 1 first, 2
    /// second, ...); NaN when they do not form on the solved path.
    double
    formation_density(unsigned int k) const
    {
      return k >= 1 && k <= formations.size()
               ? formations[k - 1].relative_density
               : std::numeric_limits<double>::quiet_NaN();
    }
  };

  /**
   * Follows a configuration from epsilon = 0 to max_strain in equal steps
   * with one formulation, and locates the formation of each family of
   * contacts. Stops at the first step where the nonlocal formulation has
   * no solution.
   */
  CrystalPath
  compute_crystal_path(CrystalConfiguration      configuration,
                       const CrystalMaterial    &material,
                       CrystalFormulation        formulation,
                       const CrystalPathOptions &options);
} // namespace compax::dem
