#pragma once
// A periodic simple cubic lattice for the FE2 tests (a Bravais lattice:
// its affine deformation is an equilibrium, so its response is the pair
// law's, written out by hand in the tests).
#include "dem/rve/periodic_bed.h"
#include "dem/solver/contact_model.h"

namespace compax::testing
{
  /// 2 x 2 x 2 simple cubic cell of spheres of radius R at spacing a,
  /// virgin histories.
  inline dem::PeriodicBed
  simple_cubic_cell(const double             a,
                    const double             R,
                    const dem::ContactModel &model)
  {
    dem::PeriodicBed bed;
    bed.cell = dem::PeriodicCell::box(Eigen::Vector3d::Constant(2 * a),
                                      {true, true, true});
    bed.reference_lattice = bed.cell.lattice();
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k)
          bed.particles.add(a * Eigen::Vector3d(i, j, k), R);
    bed.contacts.set_skin(0.3 * R);
    bed.contacts.rebuild(bed.particles, bed.cell, model);
    return bed;
  }
} // namespace compax::testing
