#pragma once
// Shared pieces of the FE2 tests: a periodic simple cubic lattice (a
// Bravais lattice: its affine deformation is an equilibrium, so its
// response is the pair law's, written out by hand in the tests), the
// contact model, and a small drawn-packing material spec.
#include "coupling/rve_material.h"
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

  /// The contact model of the FE2 tests: Material 1 of Gonzalez 2018
  /// (E = 5 GPa, nu = 0.25, plastic stress 150 MPa, m = 2; K_Ic 1.26 MPa
  /// m^1/2).
  inline dem::ContactModel
  material1()
  {
    return dem::ContactModel(dem::ElastoplasticMaterial{5e9, 0.25, 150e6, 2.0},
                             1.26e6);
  }

  /// FE2 points of one drawn 60-particle packing, solved tightly (the
  /// tests compare states to 1e-12).
  inline coupling::RveMaterialSpec
  small_drawn_spec()
  {
    coupling::RveMaterialSpec spec;
    spec.packing.particle_count              = 60;
    spec.packing.sizes.median_radius         = 220e-6;
    spec.packing.seed                        = 9;
    spec.pool_size                           = 1;
    spec.loading.equilibrium.force_tolerance = 1e-10;
    spec.loading.equilibrium.step_tolerance  = 1e-10;
    return spec;
  }
} // namespace compax::testing
