#include "apps/tablet/multiscale_parameters.h"

#include "apps/cli/parameters.h"
#include "apps/database/database_outputs.h"
#include "coupling/multiscale_database_material.h"
#include "coupling/parameters/database_parameters.h"
#include "coupling/rve_database_archive.h"
#include "coupling/rve_material.h"

#include <iostream>

namespace compax::cli
{
  fem::MaterialRegistry
  tablet_materials()
  {
    fem::MaterialRegistry materials = fem::closed_form_materials();
    materials.add({"multiscale-database",
                   "an RVE response database is built first (subsection "
                   "Multiscale) and the Drucker-Prager Cap fitted to it "
                   "drives the tablet",
                   {},
                   {}});
    materials.add({"multiscale-fe2",
                   "an RVE per quadrature point (subsection Multiscale; "
                   "experimental: with small cells it does not yet get past "
                   "the jamming transition)",
                   {},
                   {}});
    return materials;
  }

  void
  declare_multiscale_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Multiscale");
    coupling::declare_database_parameters(prm);
    prm.declare_entry("Pool size",
                      "4",
                      dealii::Patterns::Integer(1, 1000),
                      "multiscale-fe2: distinct RVE packings; the quadrature "
                      "points of cell n start from copies of packing n mod "
                      "pool size "
                      "(start-up costs this many packings), in [1, 1000]. "
                      "Unit: -.");
    declare_quantity(prm,
                     "Tangent floor modulus",
                     "1e6",
                     non_negative(),
                     "Pa",
                     "multiscale-fe2: Young's modulus of a weak isotropic "
                     "hypoelastic skeleton (Poisson's ratio 0.25) in "
                     "parallel with each RVE, so that points whose powder "
                     "has no contact network yet keep the continuum Newton "
                     "well-posed; what it adds to the stress is set by "
                     "Tangent floor stress.");
    prm.declare_entry(
      "Tangent floor stress",
      "released-at-jamming",
      dealii::Patterns::Selection("released-at-jamming|accumulated"),
      "multiscale-fe2: released-at-jamming (default): the floor's stress is "
      "integrated while a point is loose and released when the point "
      "switches to its jammed packing (whose stress, the jamming pressure, "
      "already is that of the powder consolidated to it); from then on the "
      "floor only adds its stiffness to the tangent (a modified Newton "
      "whose error is multiplied by at most Ef / (Ef + E_RVE) per iteration), "
      "so "
      "none of its compaction stress remains in the ejected tablet. "
      "accumulated: the "
      "former scheme, the floor's stress integrated over the whole cycle "
      "and added to the RVE's (Ef x the summed strain increments, a mean "
      "stress of -0.4 MPa after uniaxial compaction from 0.5 to 0.9 at "
      "1 MPa, stays in the ejected tablet, balanced by tension in its "
      "RVEs). Unit: -.");
    prm.declare_entry("FE2 stress resolution",
                      "1e-3",
                      dealii::Patterns::Double(0.0, 0.1),
                      "multiscale-fe2: relative accuracy of the homogenized "
                      "stress; the continuum Newton tolerance is raised to "
                      "it, in [0, 0.1]. An RVE's stress is piecewise smooth: "
                      "contact events change it by ~1e-4 of its magnitude "
                      "between neighbouring trial strains, below which "
                      "Newton cannot balance it. Unit: -.");
    prm.leave_subsection();
  }

  void
  check_multiscale_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Multiscale");
    coupling::get_database_setup(prm, "Multiscale/");
    prm.leave_subsection();
  }

  std::shared_ptr<fem::MaterialModel>
  make_multiscale_material(
    dealii::ParameterHandler                        &prm,
    const std::string                               &model,
    const std::filesystem::path                     &folder,
    const unsigned int                               compaction_axis,
    const unsigned int                               points_per_cell,
    MPI_Comm                                         comm,
    std::optional<coupling::RveDatabaseStudyResult> *database)
  {
    // What the database and the RVE states depend on.
    const std::string parameters = canonical_parameters(prm, {"Multiscale"});
    prm.enter_subsection("Multiscale");
    coupling::DatabaseSetup setup
      = coupling::get_database_setup(prm, "Multiscale/");
    // The tablet's fill density may lie below a deposit's: the RVEs then
    // start from the deposit (see Packing/Protocol).
    setup.spec.denser_deposit = dem::DenserDeposit::keep;
    coupling::RveMaterialSpec fe2;
    fe2.packing               = setup.spec.packing;
    fe2.loading               = setup.spec.loading;
    fe2.pool_size             = prm.get_integer("Pool size");
    fe2.tangent_floor_modulus = prm.get_double("Tangent floor modulus");
    fe2.floor_stress
      = prm.get("Tangent floor stress") == "accumulated"
          ? coupling::RveMaterialSpec::FloorStress::accumulated
          : coupling::RveMaterialSpec::FloorStress::released_at_jamming;
    fe2.compaction_axis       = compaction_axis;
    fe2.points_per_cell       = points_per_cell;
    fe2.stress_resolution     = prm.get_double("FE2 stress resolution");
    fe2.checkpoint_parameters = parameters;
    prm.leave_subsection();

    if (model == "multiscale-fe2")
      return std::make_shared<coupling::RveMaterial>(fe2, setup.cell.model);

    coupling::MultiscaleDatabaseObserver observer;
    observer.started = [&setup] {
      std::cout << "RVE response database ("
                << setup.spec.packing.particle_count << " particles, "
                << setup.cell.size_description << "):" << std::endl;
    };
    observer.progress
      = [](const std::string &line) { std::cout << "  " << line << std::endl; };
    observer.built = [&](const coupling::RveDatabaseStudyResult &result) {
      for (const std::string &n : result.notes)
        std::cout << "  note: " << n << std::endl;
      const std::filesystem::path out = folder / "database";
      std::filesystem::create_directories(out);
      write_database_rows(out, result.database);
      coupling::write_database_archive(out / "database.h5",
                                       result.database,
                                       parameters);
      write_dpc_table(out, result.fit);
      if (database)
        *database = result;
    };
    return coupling::make_multiscale_database_material(setup.spec,
                                                       setup.cell.model,
                                                       comm,
                                                       observer);
  }
} // namespace compax::cli
