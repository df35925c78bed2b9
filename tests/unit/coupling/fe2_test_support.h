#pragma once
// Shared pieces of the FE2 tests: a periodic simple cubic lattice (a
// Bravais lattice: its affine deformation is an equilibrium, so its
// response is the pair law's, written out by hand in the tests) and a
// small drawn-packing material spec of Material 1 (its contact model is
// material1::contact_model()).
#include "coupling/rve_material.h"
#include "dem/rve/periodic_bed.h"
#include "dem/solver/contact_model.h"
#include "tests/support/gonzalez_material1.h"

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

  /// FE2 points of one drawn 60-particle packing, solved tightly (the
  /// tests compare states to 1e-12).
  inline coupling::RveMaterialSpec
  small_drawn_spec()
  {
    coupling::RveMaterialSpec spec;
    spec.packing.particle_count              = 60;
    spec.packing.sizes.median_radius         = material1::R;
    spec.packing.seed                        = 9;
    spec.pool_size                           = 1;
    spec.loading.equilibrium.force_tolerance = 1e-10;
    spec.loading.equilibrium.step_tolerance  = 1e-10;
    return spec;
  }
} // namespace compax::testing
