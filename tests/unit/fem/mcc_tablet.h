#pragma once

// The tablet of the Drucker-Prager cap tests: microcrystalline cellulose
// (the built-in DPC table) in a 10 mm die.

#include "fem/drucker_prager_cap.h"
#include "fem/tablet_process.h"
#include "fem/tablet_solver.h"

#include <memory>

namespace compax::testing
{
  /// A 10 mm die filled 7 mm high at relative density 0.5, die-wall
  /// friction 0.25, @p radial_cells cells across the radius.
  inline fem::TabletSolverSettings
  mcc_tablet_settings(const unsigned int radial_cells = 4)
  {
    fem::TabletSolverSettings s;
    s.geometry.die_diameter    = 10e-3;
    s.geometry.fill_height     = 7e-3;
    s.geometry.n_radial_cells  = radial_cells;
    s.wall_friction            = 0.25;
    s.initial_relative_density = 0.5;
    return s;
  }

  /// The DPC model of microcrystalline cellulose.
  inline std::shared_ptr<fem::DruckerPragerCap>
  mcc_material()
  {
    return std::make_shared<fem::DruckerPragerCap>(
      fem::DpcTable::microcrystalline_cellulose());
  }

  /// A short cycle: 20 compaction, 5 unloading and 6 ejection steps (2 mm).
  inline fem::TabletProcess
  mcc_short_cycle()
  {
    fem::TabletProcess p;
    p.compaction_steps      = 20;
    p.unloading_steps       = 5;
    p.ejection_displacement = 2e-3;
    p.ejection_steps        = 6;
    return p;
  }
} // namespace compax::testing
