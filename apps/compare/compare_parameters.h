#pragma once

#include "coupling/scale_comparison.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace compax::cli
{
  /// Entries of a sub-study's ParameterHandler ("Packing/Die diameter")
  /// and their values.
  using Settings = std::vector<std::pair<std::string, std::string>>;

  /// What `compax compare` reads from its parameters: what the comparison
  /// is made at, and what its sub-studies are set up from.
  struct CompareSetup
  {
    /// Die diameter, final density, unloading points, loose branches and
    /// the ejection pressure's friction coefficient.
    coupling::ScaleComparisonSettings comparison;
    /// Die/Unloading points as written, for messages.
    std::string unloading_list;
    Settings    material; // Material/... entries
    Settings    bonding;  // Bonding/... entries
    Settings    die;      // everything for compax die
    int         rve_particles = 0, rve_seed = 0, rve_shear_steps = 0;
    double      rve_strain_step   = 0.0;
    double      rve_final_density = 0.0;
    int         tablet_cells = 0, tablet_steps = 0, tablet_unloading_steps = 0;
    bool        fe2           = true;
    int         fe2_particles = 0, fe2_pool = 0, fe2_cells = 0, fe2_steps = 0,
        fe2_cuts     = 0;
    double fe2_floor = 0.0;
  };

  /// Declares the subsections Compare, Material, Bonding, Die, RVE and
  /// Tablet.
  void
  declare_compare_parameters(dealii::ParameterHandler &prm);

  /// Reads and cross-checks them; throws InputError naming the entry.
  CompareSetup
  read_compare_setup(dealii::ParameterHandler &prm);
} // namespace compax::cli
