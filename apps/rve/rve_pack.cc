#include "apps/rve/rve_pack.h"

#include "dem/rve/rve_packing.h"

#include <iostream>

namespace compax::cli
{
  void
  print_packing(const coupling::RveStudy       &study,
                const dem::PeriodicPackingSpec &spec)
  {
    const bool deposited = spec.protocol == dem::PackingProtocol::deposited;
    std::cout << "Packing " << spec.particle_count
              << " spheres in a periodic cell (" << study.size_description
              << ", seed " << spec.seed << ", "
              << (deposited ? "deposited, compacted uniaxially"
                            : "compressed gas")
              << ") to a relative density of " << spec.relative_density
              << " ..." << std::endl;
  }

  void
  print_packed(const coupling::RveStudy       &study,
               const dem::PeriodicPackingSpec &spec,
               const dem::PeriodicBed         &bed)
  {
    if (spec.protocol == dem::PackingProtocol::deposited)
      std::cout << "  deposit compacted on the "
                << (dem::packing_loading(study).consolidation
                        == dem::RveConsolidation::none
                      ? "bonded path"
                      : "frozen-history path")
                << std::endl;
    std::cout << "  cell edge " << bed.cell.lattice()(0, 0) << " m = "
              << bed.cell.lattice()(0, 0) / (2.0 * bed.particles.mean_radius())
              << " mean diameters" << std::endl;
  }

  dem::PeriodicBed
  pack_rve(const coupling::RveStudy       &study,
           const dem::PeriodicPackingSpec &spec)
  {
    print_packing(study, spec);
    dem::PeriodicBed bed;
    try
      {
        bed = dem::make_rve_packing(spec,
                                    study.model,
                                    dem::packing_loading(study));
      }
    catch (const dem::DepositDensityError &e)
      {
        coupling::reject_deposit_density(spec, e.deposit_density);
      }
    print_packed(study, spec, bed);
    return bed;
  }
} // namespace compax::cli
