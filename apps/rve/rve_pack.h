#pragma once

#include "coupling/parameters/rve_parameters.h"
#include "dem/rve/periodic_bed.h"
#include "dem/rve/periodic_packing.h"

namespace compax::cli
{
  /// The line on screen before a cell of `spec` is packed.
  void
  print_packing(const coupling::RveStudy       &study,
                const dem::PeriodicPackingSpec &spec);

  /// The lines on screen once it is packed.
  void
  print_packed(const coupling::RveStudy       &study,
               const dem::PeriodicPackingSpec &spec,
               const dem::PeriodicBed         &bed);

  /// The packing of one run, with its lines on screen; a deposit denser
  /// than asked is bad input (coupling::reject_deposit_density()).
  dem::PeriodicBed
  pack_rve(const coupling::RveStudy       &study,
           const dem::PeriodicPackingSpec &spec);
} // namespace compax::cli
