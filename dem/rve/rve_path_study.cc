#include "dem/rve/rve_path_study.h"

#include "dem/rve/periodic_bed_system.h"
#include "dem/solver/trust_region_newton.h"
#include "dem/wall_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

namespace compax::dem
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    using Clock = std::chrono::steady_clock;

    /// The symmetric part of a tangent: the elastic constants are read
    /// from it (a Cauchy-stress tangent carries a non-symmetric -sigma
    /// tr(eps) term).
    Matrix6d
    symmetric(const Matrix6d &C)
    {
      return 0.5 * (C + C.transpose());
    }

    bool
    every(const int interval, const int k)
    {
      return interval > 0 && k % interval == 0;
    }
  } // namespace

  RveLoadingOptions
  packing_loading(const RvePathStudyOptions &options)
  {
    RveLoadingOptions loading = options.loading;
    if (options.elastic)
      loading.consolidation = RveConsolidation::frozen_history;
    return loading;
  }

  RvePathStudy::RvePathStudy(ContactModel        model,
                             RvePathStudyOptions options,
                             RvePathState        state)
      : model_(std::move(model))
      , options_(std::move(options))
      , state_(std::move(state))
  {
  }

  RvePathResult
  RvePathStudy::run(const RvePathObserver &observer)
  {
    const auto          started = Clock::now();
    RvePathResult       out;
    RvePathTimings     &timing = out.timings;
    RvePathState       &s      = state_;
    PeriodicBed        &bed    = s.bed;
    const auto         &model  = model_;
    const auto         &o      = options_;
    const RveStrainPath path   = o.path;

    auto loading = std::make_unique<RveLoading>(model, o.loading);
    // Elastic spheres (Hertz or nonlocal): their own stepper, stress and
    // coordination; no tangents.
    std::unique_ptr<NonlocalRveLoading> elastic;
    if (o.elastic)
      elastic = std::make_unique<NonlocalRveLoading>(*o.elastic);
    // F_k F_{k-1}^{-1} - I of the last step (the direction of the trial
    // state of a finite-difference check).
    Eigen::Matrix3d    last_increment = Eigen::Matrix3d::Zero();
    auto               tangent        = std::make_unique<TangentCalculator>();
    EquilibriumOptions fd_options     = o.loading.equilibrium;
    fd_options.force_tolerance
      = std::min(fd_options.force_tolerance, o.fd_force_tolerance);
    fd_options.step_tolerance
      = std::min(fd_options.step_tolerance, o.fd_force_tolerance);

    // The current state as a step; jamming is sticky.
    const auto record = [&](const bool                 unloading,
                            const RveStepResult *const r,
                            const double               seconds) {
      RvePathStep step;
      step.step             = s.step();
      step.unloading        = unloading;
      step.relative_density = bed.relative_density();
      step.strain           = logarithmic_strain(bed.deformation);
      step.stress = elastic ? elastic->stress(bed) : love_weber_stress(bed);
      if (elastic)
        {
          step.measures.coordination_number = elastic->coordination(bed);
          step.measures.coordination_without_rattlers = nan;
          step.measures.rattler_fraction              = nan;
        }
      else
        step.measures = measure_rve(bed);
      if (r)
        step.solve = *r;
      step.seconds    = seconds;
      s.unloading     = unloading;
      s.axial_stress  = step.stress(2, 2);
      s.mean_pressure = -step.stress.trace() / 3.0;
      if (s.mean_pressure >= o.loading.jamming_pressure)
        s.jammed = true;
      out.steps.push_back(std::move(step));
    };

    // Tangents and moduli at the current state (jammed cells of the
    // bonded law only: a loose cell has no stiffness; a bonded cell in
    // tension has); the finite-difference check if asked.
    const auto moduli = [&](const bool unloading, const bool check) {
      if (elastic || std::abs(mean_pressure(bed)) < o.loading.jamming_pressure)
        return;
      RvePathModuli m;
      m.step             = s.step();
      m.unloading        = unloading;
      m.relative_density = bed.relative_density();
      const auto t0      = Clock::now();
      m.current          = tangent->compute(bed, model, ContactBranch::current);
      m.seconds          = seconds_since(t0);
      timing.tangents += m.seconds;
      ++timing.n_tangents;
      m.unloading_condensed
        = tangent->compute(bed, model, ContactBranch::unloading).condensed;
      m.isotropic = isotropic_projection(symmetric(m.unloading_condensed));
      try
        {
          m.transversely_isotropic
            = transversely_isotropic_moduli(symmetric(m.unloading_condensed));
        }
      catch (const std::domain_error &)
        {
          // Not positive definite (a barely jammed cell): left empty.
        }
      m.condensed_projection
        = transversely_isotropic_projection(symmetric(m.current.condensed));
      m.affine_projection
        = transversely_isotropic_projection(symmetric(m.current.affine));
      if (check)
        {
          // At a trial state half a step further along the path,
          // equilibrated with frozen histories: a converged state puts
          // every loading contact on the kink between its plastic and
          // elastic branches, where a central difference approximates
          // neither; past it each contact is strictly on one branch.
          const auto  t1    = Clock::now();
          PeriodicBed trial = bed;
          map_affinely(trial,
                       (Eigen::Matrix3d::Identity() + 0.5 * last_increment)
                         * bed.deformation);
          PeriodicAssembler assembler;
          PeriodicBedSystem system(trial, model, assembler);
          TrustRegionNewton newton(fd_options);
          const bool        ok = newton.solve(system).converged;
          try
            {
              if (!ok)
                throw std::runtime_error("the trial state did not converge");
              const Matrix6d c
                = TangentCalculator()
                    .compute(trial, model, ContactBranch::current)
                    .condensed;
              const Matrix6d fd = finite_difference_tangent(trial,
                                                            model,
                                                            o.fd_strain_step,
                                                            fd_options);
              m.fd_error        = (c - fd).norm() / fd.norm();
            }
          catch (const std::runtime_error &e)
            {
              if (observer.note)
                observer.note(std::string("finite-difference check skipped: ")
                              + e.what());
            }
          timing.fd_tangents += seconds_since(t1);
          ++timing.n_fd_tangents;
        }
      out.moduli.push_back(std::move(m));
    };

    const auto notify
      = [&](const bool initial, const bool end_of_stage, const bool stopping) {
          if (observer.state)
            observer.state({s, out, initial, end_of_stage, stopping});
        };

    if (!s.started)
      {
        s.initial_density = bed.relative_density();
        record(false, nullptr, 0.0);
        s.started = true;
        moduli(false, false);
        notify(true, false, false);
      }
    // A fresh loading takes over the sticky jamming of the path so far.
    const auto keep_jammed = [&] {
      if (s.jammed)
        loading->set_jammed();
    };
    keep_jammed();

    const auto after_step = [&](const bool unloading, const bool end_of_stage) {
      const int  step  = s.step();
      const bool check = every(o.fd_interval, step);
      if (every(o.tangent_interval, step) || end_of_stage || check)
        moduli(unloading, check);
      const bool stop = o.stop_after > 0 && step >= o.stop_after;
      notify(false, end_of_stage, stop);
      // Every step starts afresh from the state a checkpoint would hold,
      // as a resumed run does: the results depend neither on the
      // checkpoint interval nor on where a run was stopped and resumed.
      bed.contacts.rebuild(bed.particles, bed.cell, model);
      loading = std::make_unique<RveLoading>(model, o.loading);
      keep_jammed();
      tangent = std::make_unique<TangentCalculator>();
      if (o.elastic)
        elastic = std::make_unique<NonlocalRveLoading>(*o.elastic);
      return stop;
    };

    // One step to F (or by a strain increment); false if it failed.
    const auto advance = [&](const bool             unloading,
                             const Eigen::Matrix3d &target,
                             const Eigen::Matrix3d *increment) {
      const auto            t0     = Clock::now();
      const Eigen::Matrix3d F_prev = bed.deformation;
      const RveStepResult   r
        = elastic ? (increment ? elastic->apply_strain(bed, *increment)
                               : elastic->deform_to(bed, target))
                  : (increment ? loading->apply_strain(bed, *increment)
                               : loading->deform_to(bed, target));
      const double seconds = seconds_since(t0);
      if (!r.converged)
        return false;
      last_increment
        = bed.deformation * F_prev.inverse() - Eigen::Matrix3d::Identity();
      timing.steps += seconds;
      ++timing.n_steps;
      (unloading ? s.unloading_done : s.loading_done) += 1;
      record(unloading, &r, seconds);
      return true;
    };

    const auto fail = [&](const std::string &why) {
      out.converged = false;
      out.failure   = why;
    };

    const double rho0           = s.initial_density;
    const int    loading_steps  = o.steps;
    const auto   loading_target = [&](const int k) {
      const double rho
        = rho0 + (o.target_density - rho0) * double(k) / loading_steps;
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      if (path == RveStrainPath::uniaxial)
        F(2, 2) = rho0 / rho;
      else
        F *= std::cbrt(rho0 / rho);
      return F;
    };
    const auto report = [&] {
      if (observer.step)
        observer.step({out.steps.back(), s, timing});
    };

    try
      {
        bool stop = false;
        while (!stop && s.loading_done < loading_steps && out.converged)
          {
            const int  k  = s.loading_done + 1;
            const bool ok = path == RveStrainPath::increments
                              ? advance(false, {}, &o.increments[k - 1])
                              : advance(false, loading_target(k), nullptr);
            if (!ok)
              {
                fail("loading step " + std::to_string(k) + " did not converge");
                break;
              }
            if (s.loading_done == loading_steps)
              s.loaded_deformation = bed.deformation;
            report();
            stop = after_step(false, s.loading_done == loading_steps);
          }
        const auto unloaded = [&] {
          if (!s.unloading)
            return false;
          // Elastic spheres unload to zero stress asymptotically: the
          // relaxation of a loose cell resolves stresses down to its force
          // floor, about force_floor_fraction times the jamming pressure.
          const double resolution = elastic ? o.loading.force_floor_fraction
                                                * o.loading.jamming_pressure
                                            : 0.0;
          return path == RveStrainPath::uniaxial
                   ? s.axial_stress >= -resolution
                   : s.mean_pressure <= resolution;
        };
        while (!stop && o.unload && out.converged
               && s.loading_done == loading_steps && !unloaded()
               && s.unloading_done < o.max_unloading_steps)
          {
            const int              u     = s.unloading_done + 1;
            const Eigen::Matrix3d &F_max = s.loaded_deformation;
            Eigen::Matrix3d        F     = F_max;
            if (path == RveStrainPath::uniaxial)
              F.row(2) *= std::exp(u * o.unloading_step);
            else if (path == RveStrainPath::hydrostatic)
              F *= std::exp(u * o.unloading_step);
            else
              {
                if (u > loading_steps)
                  break;
                // Undo the increments in reverse order: F_{k-1} = (I +
                // eps_k)^{-1} F_k.
                F = (Eigen::Matrix3d::Identity()
                     + o.increments[loading_steps - u])
                      .inverse()
                    * bed.deformation;
              }
            if (!advance(true, F, nullptr))
              {
                fail("unloading step " + std::to_string(u)
                     + " did not converge");
                break;
              }
            report();
            const bool last = unloaded()
                              || s.unloading_done == o.max_unloading_steps
                              || (path == RveStrainPath::increments
                                  && s.unloading_done == loading_steps);
            stop = after_step(true, last);
          }
        out.stopped = stop;
      }
    catch (const std::runtime_error &e)
      {
        fail(e.what());
      }
    timing.total = seconds_since(started);
    return out;
  }
} // namespace compax::dem
