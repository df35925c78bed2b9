#include "dem/die/jamming_study.h"

#include "dem/analysis/jamming_fit.h"
#include "dem/wall_clock.h"

#include <chrono>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace compax::dem
{
  std::vector<DieRecord>
  jammed_compaction(const std::vector<DieRecord> &records,
                    const double                  pressure_resolution)
  {
    std::vector<DieRecord> jammed;
    for (const DieRecord &r : records)
      if (r.stage == "compaction" && r.step > 0 && r.coordination_number > 0
          && r.upper_punch_pressure > pressure_resolution)
        jammed.push_back(r);
    return jammed;
  }

  std::optional<CoordinationFit>
  fit_jamming(const std::vector<DieRecord> &records,
              const double                  pressure_resolution,
              const DieRegion               region)
  {
    const bool                   interior = region == DieRegion::interior;
    std::vector<CompactionState> states;
    for (const DieRecord &r : records)
      if (r.stage == "compaction" && r.step > 0
          && (!interior || std::isfinite(r.rho_interior)))
        states.push_back(interior ? CompactionState{r.rho_interior,
                                                    -r.sigma_zz_interior,
                                                    r.coordination_interior}
                                  : CompactionState{r.relative_density,
                                                    r.upper_punch_pressure,
                                                    r.coordination_number});
    return fit_jamming(states, pressure_resolution);
  }

  std::string
  JammingCase::protocol_name() const
  {
    return frozen_history ? "frozen-history" : "bonded-path";
  }

  ContactModel
  with_fracture_toughness(const ContactModel &model,
                          const double        fracture_toughness)
  {
    ContactModel result = model;
    result.set_fracture_toughness(fracture_toughness);
    return result;
  }

  JammingResult
  run_jamming_case(const Bed                &deposit,
                   const ContactModel       &model,
                   DieProtocol               protocol,
                   const EquilibriumOptions &equilibrium,
                   const JammingCase        &study_case,
                   std::ostream             *progress)
  {
    protocol.consolidate = study_case.frozen_history;
    protocol.unloading_points.clear();
    protocol.checkpoint_interval = 0;
    protocol.stop_after          = 0;
    const ContactModel case_model
      = with_fracture_toughness(model, study_case.fracture_toughness);
    DieCompaction die(deposit, case_model, protocol, equilibrium);
    die.set_output(nullptr, progress);

    JammingResult result;
    result.study_case = study_case;
    const auto t0     = std::chrono::steady_clock::now();
    try
      {
        die.run();
      }
    catch (const std::runtime_error &e)
      {
        result.failure = die.failed() ? die.failure() : e.what();
      }
    result.seconds         = seconds_since(t0);
    result.records         = die.records();
    result.jamming_density = die.jamming_density();
    // The first compaction row at or past it (the frozen-history
    // consolidation ends between two targets).
    for (const DieRecord &r : result.records)
      if (r.stage == "compaction" && result.jamming_density > 0.0
          && r.relative_density >= result.jamming_density)
        {
          result.jamming_coordination = r.coordination_number;
          break;
        }
    result.fit = fit_jamming(result.records, die.pressure_resolution());
    result.interior_fit = fit_jamming(result.records,
                                      die.pressure_resolution(),
                                      DieRegion::interior);
    return result;
  }

  void
  write_jamming_csv(std::ostream                     &out,
                    const std::string                &material,
                    const std::string                &contact_law,
                    const std::vector<JammingResult> &results)
  {
    const auto old = out.precision(10);
    out << "material,fracture_toughness,protocol,rho_c_Z,Z_c,theta,"
           "rho_jammed,Z_jammed,rho_c_Z_interior,Z_c_interior,"
           "theta_interior,contact_law\n";
    const auto write_fit = [&out](const std::optional<CoordinationFit> &fit) {
      if (fit)
        out << fit->rho_c << ',' << fit->Z_c << ',' << fit->theta;
      else
        out << ",,";
    };
    for (const JammingResult &r : results)
      {
        out << material << ',' << r.study_case.fracture_toughness << ','
            << r.study_case.protocol_name() << ',';
        write_fit(r.fit);
        out << ',' << r.jamming_density << ',' << r.jamming_coordination << ',';
        write_fit(r.interior_fit);
        out << ',' << contact_law << '\n';
      }
    out.precision(old);
  }
} // namespace compax::dem
