#pragma once

#include "dem/dynamics/uniaxial_compaction.h"

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace compax::cli
{
  /// Everything a compaction run of `compax mcdem` or `compax calibrate`
  /// reads from its parameter file.
  struct McdemSetup
  {
    dem::DemMaterial        material;
    dem::DynamicsSettings   settings;
    dem::RveSpec            rve;
    dem::CompactionProtocol protocol;
    /// Edges of the cubes of the RVE-size study (one: a single run) [m].
    std::vector<double> cell_sizes;
    /// The volume log-normal fitted to Table 1's x10, x50, x90.
    double fitted_median_diameter = 0.0, fitted_log_sigma = 0.0;
  };

  /**
   * Declares the subsections Material (Giannis 2021 Table 2), Multi-contact
   * law (Table 3), Particle size distribution (Table 1), Cell, Protocol
   * and Numerics, with MCC-A as the default material.
   *
   * @param mass_scaling default of Numerics/Mass scaling
   * @param strain_rate default of Protocol/Strain rate [1/s]
   */
  void
  declare_mcdem_parameters(dealii::ParameterHandler &prm,
                           double                    mass_scaling,
                           double                    strain_rate);

  /// Reads them (and checks relations between entries: InputError).
  McdemSetup
  get_mcdem_setup(dealii::ParameterHandler &prm);
} // namespace compax::cli
