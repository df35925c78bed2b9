#pragma once

#include "dem/dynamics/uniaxial_compaction.h"

#include <functional>
#include <string>
#include <vector>

namespace compax::dem
{
  /// A stress-strain curve: loading (stage 1) then unloading (stage 2).
  struct StressStrainCurve
  {
    std::vector<double> strain; ///< compression positive [-]
    std::vector<double> stress; ///< compression positive [Pa]
    std::vector<int>    stage;  ///< 1 loading, 2 unloading
  };

  /// R^2 = 1 - sum (y - y_hat)^2 / sum (y - mean y)^2 (Giannis 2021,
  /// Eq. 15): y measured, y_hat simulated.
  double
  coefficient_of_determination(const std::vector<double> &measured,
                               const std::vector<double> &simulated);

  /**
   * The simulated stress at each measured point: interpolated linearly in
   * strain on the branch of the same stage (loading where strain grows,
   * unloading, from the turning point, where it falls). Beyond the simulated
   * range of a branch the end value is used on loading, and zero stress below
   * the strain where the simulated unloading lost contact.
   */
  std::vector<double>
  simulated_at(const StressStrainCurve &measured,
               const StressStrainCurve &simulated);

  /// Options of nelder_mead().
  struct NelderMeadOptions
  {
    /// Initial simplex edge, in the units of x.
    std::vector<double> initial_step;
    /// Lower and upper bounds of x (points are clamped into the box).
    std::vector<double> lower, upper;
    /// Stop when f <= this value.
    double target = -1e300;
    /// Stop after this many evaluations of f.
    int max_evaluations = 100;
    /// Stop when the simplex's f values differ by less than this.
    double f_tolerance = 1e-10;
  };

  /// Result of nelder_mead().
  struct NelderMeadResult
  {
    std::vector<double> x;
    double              f           = 0.0;
    int                 evaluations = 0;
  };

  /**
   * Minimizes f by the Nelder-Mead simplex (reflection 1, expansion 2,
   * contraction 1/2, shrink 1/2) inside a box: a derivative-free search,
   * since each f is a noisy DEM simulation.
   */
  NelderMeadResult
  nelder_mead(const std::function<double(const std::vector<double> &)> &f,
              std::vector<double>                                       x0,
              const NelderMeadOptions &options);

  /// Which law parameters calibrate() fits, their start and bounds.
  struct CalibrationSpec
  {
    /// Names among "k2/k1", "kc/k1", "beta".
    std::vector<std::string> parameters{"k2/k1", "kc/k1", "beta"};
    std::vector<double>      initial{50.0, 0.2, 0.5};
    std::vector<double>      lower{1.0, 0.0, 0.0};
    std::vector<double>      upper{300.0, 2.0, 5.0};
    /// Stop when R^2 exceeds this (Giannis 2021: 0.95).
    double target_r2 = 0.95;
    /// Largest number of compaction simulations.
    int max_simulations = 40;
  };

  /// One simulation of the search.
  struct CalibrationStep
  {
    MulticontactAdhesiveLaw::Parameters law;
    double                              r2;
  };

  /// Result of calibrate().
  struct CalibrationResult
  {
    MulticontactAdhesiveLaw::Parameters law; ///< best found
    double                              r2 = -1e300;
    StressStrainCurve                   best_curve;
    std::vector<CalibrationStep>        history;
    bool                                reached_target = false;
  };

  /// Runs one compaction of a prepared packing with the given law and
  /// returns its stress-strain curve.
  StressStrainCurve
  compaction_curve(const UniaxialCompaction                  &prepared,
                   const MulticontactAdhesiveLaw::Parameters &law,
                   const CompactionProtocol                  &protocol);

  /**
   * Fits the named law parameters to a measured curve by maximizing R^2
   * (Eq. 15) with Nelder-Mead over compaction simulations of one prepared
   * packing (prepared once, copied for each simulation), starting from
   * base_law with the initial values, until R^2 > target_r2 or the budget
   * is spent (Giannis 2021 §4.1.1). The protocol's target strain should be
   * the measured curve's largest strain.
   */
  CalibrationResult
  calibrate(const StressStrainCurve                            &measured,
            const UniaxialCompaction                           &prepared,
            const MulticontactAdhesiveLaw::Parameters          &base_law,
            const CompactionProtocol                           &protocol,
            const CalibrationSpec                              &spec,
            const std::function<void(const CalibrationStep &)> &on_step = {});
} // namespace compax::dem
