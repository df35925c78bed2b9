#pragma once

#include "dem/analysis/curve_fits.h"
#include "dem/die/die_compaction.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace compax::dem
{
  /// The jammed part of a compaction path: the compaction states after the
  /// deposit whose upper punch carries more than @p pressure_resolution
  /// [Pa] and whose coordination number is positive.
  std::vector<DieRecord>
  jammed_compaction(const std::vector<DieRecord> &records,
                    double                        pressure_resolution);

  /// Where in the die a jamming fit measures the bed.
  enum class DieRegion
  {
    /// The whole bed: relative density, upper punch pressure, Z.
    whole_bed,
    /// The interior (DieRecord::rho_interior, -sigma_zz_interior,
    /// coordination_interior), where a periodic cell compares.
    interior
  };

  /**
   * Eq. (14) of Gonzalez 2018, Z = Z_c + Z_0 (rho - rho_c_Z)^theta, fitted
   * to the jammed compaction states of @p region. Empty with fewer than
   * five jammed states or when the fit fails.
   */
  std::optional<CoordinationFit>
  fit_jamming(const std::vector<DieRecord> &records,
              double                        pressure_resolution,
              DieRegion                     region = DieRegion::whole_bed);

  /// How one compaction of a jamming study treats bonding and the loose
  /// regime.
  struct JammingCase
  {
    /// K_Ic of every pair of materials [Pa m^1/2]; 0: no solid bridges.
    double fracture_toughness = 0.0;
    /// true: the frozen-history consolidation (DieProtocol::consolidate);
    /// false: the bonded path from the deposit.
    bool frozen_history = false;

    /// "bonded-path" or "frozen-history", as in jamming.csv.
    std::string
    protocol_name() const;
  };

  /// The outcome of one case.
  struct JammingResult
  {
    JammingCase                    study_case;
    std::optional<CoordinationFit> fit;
    /// Eq. (14) fitted to the die's interior (DieRecord::rho_interior,
    /// -sigma_zz_interior, coordination_interior): the region a periodic
    /// cell represents, without the looser wall layer.
    std::optional<CoordinationFit> interior_fit;
    /// The compaction path (die.csv rows, no branches).
    std::vector<DieRecord> records;
    /// DieCompaction::jamming_density(): the first state whose punches
    /// carry the jamming pressure (0.5 MPa) [-]; 0 if not reached.
    double jamming_density = 0.0;
    /// The coordination number there (frozen-history: of the first load
    /// step after the consolidation) [-].
    double jamming_coordination = 0.0;
    /// Empty, or why the compaction stopped early (the rows so far are
    /// kept and fitted).
    std::string failure;
    /// Wall time of the compaction [s] (timing only).
    double seconds = 0.0;
  };

  /**
   * The jamming study of Gonzalez 2018 Sec. 5.1 as a comparison of
   * protocols: one deposit compacted (no unloading) once per case, with
   * the model's materials and the case's fracture toughness, and Eq. (14)
   * fitted to each path. The bed jams where the bonded network first
   * carries the jamming pressure; comparing K_Ic > 0 with K_Ic = 0 on the
   * same deposit isolates what the bridges do to the onset.
   */
  JammingResult
  run_jamming_case(const Bed                &deposit,
                   const ContactModel       &model,
                   DieProtocol               protocol,
                   const EquilibriumOptions &equilibrium,
                   const JammingCase        &study_case,
                   std::ostream             *progress = nullptr);

  /// The model with every K_Ic replaced by @p fracture_toughness [Pa
  /// m^1/2] (materials, regularisation, wall bonding and a registered law
  /// unchanged).
  ContactModel
  with_fracture_toughness(const ContactModel &model, double fracture_toughness);

  /// jamming.csv: material,fracture_toughness,protocol,rho_c_Z,Z_c,theta
  /// (Eq. 14; empty cells where it could not be fitted), then
  /// rho_jammed,Z_jammed (where the punches first carried the jamming
  /// pressure; a measure that needs no fit), then
  /// rho_c_Z_interior,Z_c_interior,theta_interior (Eq. 14 of the
  /// interior, JammingResult::interior_fit), then contact_law: the law
  /// every contact followed (bonded-elastoplastic or a registered law).
  void
  write_jamming_csv(std::ostream                     &out,
                    const std::string                &material,
                    const std::string                &contact_law,
                    const std::vector<JammingResult> &results);
} // namespace compax::dem
