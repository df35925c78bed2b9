#include "apps/tablet/multiscale_material_setup.h"

#include "apps/cli/parameters.h"
#include "apps/database/database_outputs.h"
#include "coupling/multiscale_database_material.h"
#include "coupling/parameters/database_parameters.h"
#include "coupling/rve_database_archive.h"
#include "coupling/rve_material.h"

#include <iostream>

namespace compax::cli
{
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
