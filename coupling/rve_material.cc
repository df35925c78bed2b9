#include "coupling/rve_material.h"

#include "dem/rve/periodic_bed_system.h"
#include "dem/rve/rve_packing.h"
#include "dem/wall_clock.h"
#include "fem/isotropic_elasticity.h"

#include <chrono>
#include <cmath>

namespace compax::coupling
{
  namespace
  {
    // History layout.
    constexpr unsigned int stress_at = 0, density_at = 6, modulus_at = 7,
                           floor_stress_at = 8, point_at = 14, step_at = 15,
                           jammed_at = 16;

    constexpr int voigt_i[6] = {0, 1, 2, 1, 0, 0};
    constexpr int voigt_j[6] = {0, 1, 2, 2, 2, 1};

    /// A deal.II rank-2 tensor (Tensor or SymmetricTensor) as an Eigen
    /// matrix.
    template <typename Rank2Tensor>
    Eigen::Matrix3d
    to_eigen(const Rank2Tensor &t)
    {
      Eigen::Matrix3d m;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          m(i, j) = t[i][j];
      return m;
    }

    using dem::seconds_since;

    dealii::SymmetricTensor<2, 3>
    from_eigen(const Eigen::Matrix3d &m)
    {
      dealii::SymmetricTensor<2, 3> t;
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j)
          t[i][j] = 0.5 * (m(i, j) + m(j, i));
      return t;
    }
  } // namespace

  dealii::SymmetricTensor<4, 3>
  from_voigt(const dem::Matrix6d &C)
  {
    // sigma_ij = C_ijkl eps_kl with eps_kl = eps_lk = gamma/2 for a shear:
    // d sigma / d gamma_kl = C_ijkl, the Voigt entry itself.
    dealii::SymmetricTensor<4, 3> t;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        t[voigt_i[a]][voigt_j[a]][voigt_i[b]][voigt_j[b]] = C(a, b);
    return t;
  }

  namespace
  {
    /// The trial solves cap the Newton's FIRE fallback: where Newton
    /// stalls, continuation in smaller sub-steps is cheaper than relaxing
    /// a jammed cell by long FIRE runs (residual-only sweeps were ~80 % of
    /// an FE2 run's time with the die's 5000).
    dem::EquilibriumOptions
    with_short_fire(dem::EquilibriumOptions options)
    {
      options.fire_iterations = std::min(options.fire_iterations, 1000);
      return options;
    }
  } // namespace

  RveMaterial::RveMaterial(RveMaterialSpec spec, dem::ContactModel model)
      : spec(std::move(spec))
      , model(std::move(model))
      , newton(with_short_fire(this->spec.loading.equilibrium))
  {
  }

  void
  RveMaterial::make_templates(const double rho) const
  {
    const auto start = std::chrono::steady_clock::now();
    templates.clear();
    template_jamming_density.clear();
    if (!spec.pool.empty())
      {
        for (const dem::PeriodicBed &cell : spec.pool)
          {
            templates.push_back(cell);
            template_jamming_density.push_back(cell.relative_density());
          }
      }
    else
      {
        consolidate_templates(rho);
      }
    const int axis = static_cast<int>(spec.compaction_axis);
    template_modulus.clear();
    template_tangent.clear();
    for (dem::PeriodicBed &cell : templates)
      {
        template_tangent.push_back(
          from_voigt(tangent.compute(cell, model).condensed));
        template_modulus.push_back(
          std::max(template_tangent.back()[axis][axis][axis][axis], 0.0));
      }
    template_density = rho;
    counters.pool_seconds += seconds_since(start);
  }

  void
  RveMaterial::consolidate_templates(const double rho) const
  {
    Eigen::Matrix3d axial_step = Eigen::Matrix3d::Zero();
    axial_step(spec.compaction_axis, spec.compaction_axis)
      = -spec.consolidation_strain_step;
    for (unsigned int k = 0; k < spec.pool_size; ++k)
      {
        dem::PeriodicPackingSpec p = spec.packing;
        p.relative_density         = rho;
        p.seed                     = spec.packing.seed + k;
        // A deposit denser than the tablet starts at its own density.
        dem::PeriodicBed cell = dem::make_rve_packing(p,
                                                      model,
                                                      spec.loading,
                                                      spec.compaction_axis,
                                                      dem::DenserDeposit::keep);
        // One loading per packing: jamming is sticky on the bonded path.
        dem::RveLoading loading(model, spec.loading);
        // Uniaxial consolidation (the die's kinematics) to the jamming
        // pressure; the loading updates the histories on the way.
        while (dem::mean_pressure(cell) < spec.loading.jamming_pressure)
          {
            if (cell.relative_density() > 0.95
                || !loading.apply_strain(cell, axial_step).converged)
              throw std::runtime_error(
                "multiscale-fe2: pool packing " + std::to_string(k)
                + " did not jam under uniaxial compaction (relative density "
                + std::to_string(cell.relative_density()) + ")");
          }
        template_jamming_density.push_back(cell.relative_density());
        templates.push_back(std::move(cell));
      }
  }

  void
  RveMaterial::initialize(const double rho, dealii::ArrayView<double> h) const
  {
    if (templates.empty() || template_density != rho)
      make_templates(rho);
    const std::size_t point = committed.size();
    // The point owns no cell until it jams (see the class comment).
    committed.emplace_back();
    trial.emplace_back();
    committed_steps.push_back(0.0);
    for (double &v : h)
      v = 0.0;
    h[density_at] = rho;
    // The point reports its packing's jammed modulus from the start: the
    // die-wall penalty scales with it, and a penalty set by the floor
    // alone lets the die give way when the point jams.
    const std::size_t pooled = pool_member(point);
    h[modulus_at] = spec.tangent_floor_modulus + template_modulus[pooled];
    h[point_at]   = static_cast<double>(point);
    h[step_at]    = 0.0;
    h[jammed_at]  = 0.0;
  }

  std::size_t
  RveMaterial::pool_member(const std::size_t point) const
  {
    return (point / std::max(spec.points_per_cell, 1u)) % templates.size();
  }

  bool
  RveMaterial::is_jammed(dealii::ArrayView<const double> h)
  {
    return h[jammed_at] != 0.0;
  }

  dealii::SymmetricTensor<2, 3>
  RveMaterial::floor_stress(dealii::ArrayView<const double> h)
  {
    return fem::load(h, floor_stress_at);
  }

  void
  RveMaterial::catch_up(const std::size_t point,
                        const double      committed_step) const
  {
    if (committed_step == committed_steps[point] + 1.0)
      {
        dem::PeriodicBed &cell = trial[point];
        if (cell.particles.size() > 0)
          cell.contacts.update_histories(cell.particles, cell.cell);
        committed[point]       = cell;
        committed_steps[point] = committed_step;
      }
  }

  bool
  RveMaterial::solve_at(dem::PeriodicBed &cell, const Eigen::Matrix3d &F) const
  {
    try
      {
        dem::map_affinely(cell, F);
        dem::PeriodicBedSystem system(cell, model, assembler);
        newton.reset();
        return newton.solve(system).converged;
      }
    catch (const std::runtime_error &)
      {
        // E.g. a cell sheared thinner than its particles: no equilibrium
        // this point can reach; the continuum step is cut.
        return false;
      }
  }

  bool
  RveMaterial::equilibrate_at(dem::PeriodicBed       &cell,
                              const dem::PeriodicBed &start,
                              const Eigen::Matrix3d  &F) const
  {
    cell = start;
    if (solve_at(cell, F))
      return true;
    ++counters.continuations;
    // Continuation: halved sub-steps from the start of the step, grown
    // back after successes; histories stay frozen throughout.
    cell                     = start;
    const Eigen::Matrix3d F0 = start.deformation;
    dem::PeriodicBed      saved;
    double                done = 0.0, size = 0.5;
    while (done < 1.0)
      {
        const double t = std::min(1.0, done + size);
        saved          = cell;
        if (solve_at(cell, t >= 1.0 ? F : F0 + t * (F - F0)))
          {
            done = t;
            size = std::min(1.0, 2.0 * size);
          }
        else
          {
            cell = saved;
            size *= 0.5;
            if (size < 1.0 / 64.0)
              return false;
          }
      }
    return true;
  }

  bool
  RveMaterial::evaluate(const fem::MaterialIncrement   &increment,
                        dealii::ArrayView<const double> old_h,
                        dealii::ArrayView<double>       new_h,
                        fem::MaterialResponse          &response) const
  {
    const auto point = static_cast<std::size_t>(old_h[point_at]);
    catch_up(point, old_h[step_at]);

    const Eigen::Matrix3d deps         = to_eigen(increment.strain_increment);
    const Eigen::Matrix3d I            = Eigen::Matrix3d::Identity();
    const double          volume_ratio = (I + deps).determinant();
    if (!(volume_ratio > 0.0))
      return false;

    // A point switches to its jammed packing at the start of the step
    // after its density passed the packing's jamming density (decided on
    // the committed state, so that within a step the response is a smooth
    // function of the increment for the continuum Newton). The density
    // overshoot of that last unjammed step is applied to the packing as
    // uniaxial compaction, the kinematics it was consolidated in.
    dem::PeriodicBed &cell    = trial[point];
    const std::size_t pooled  = pool_member(point);
    const double      rho_old = old_h[density_at];
    const bool        jammed
      = is_jammed(old_h) || rho_old >= template_jamming_density[pooled];
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    dem::Matrix6d   C     = dem::Matrix6d::Zero();
    if (jammed)
      {
        // The RVE: equilibrium at the trial deformation, its stress and
        // condensed tangent (timed: the RVE share of an FE2 run).
        const auto solve = [&]() {
          const bool              switching = !is_jammed(old_h);
          const dem::PeriodicBed &start
            = switching ? templates[pooled] : committed[point];
          Eigen::Matrix3d overshoot = I;
          if (switching)
            overshoot(spec.compaction_axis, spec.compaction_axis)
              = template_jamming_density[pooled] / rho_old;
          const Eigen::Matrix3d F = (I + deps) * overshoot * start.deformation;
          if (!equilibrate_at(cell, start, F))
            return false;
          sigma = dem::love_weber_stress(cell);
          try
            {
              C = tangent.compute(cell, model).condensed;
            }
          catch (const std::runtime_error &)
            {
              return false;
            }
          return true;
        };
        const auto t0 = std::chrono::steady_clock::now();
        const bool ok = solve();
        counters.seconds += seconds_since(t0);
        ++counters.solves;
        if (!ok)
          {
            ++counters.failures;
            return false;
          }
      }

    // The floor is a weak hypoelastic skeleton in parallel with the RVE.
    // While the point is loose its stress is integrated like any
    // hypoelastic law's (stress and tangent consistent). By default it is
    // released when the point jams (the jammed packing's stress already is
    // the powder's, see RveMaterialSpec::FloorStress) and the floor only
    // regularises the tangent from then on, so that none of its compaction
    // stress remains in the ejected tablet.
    const double                        Ef = spec.tangent_floor_modulus;
    const dealii::SymmetricTensor<4, 3> floor
      = fem::isotropic_stiffness_tensor(Ef, 0.25);
    const bool released
      = jammed
        && spec.floor_stress
             == RveMaterialSpec::FloorStress::released_at_jamming;
    const dealii::SymmetricTensor<2, 3> floor_sigma
      = released ? dealii::SymmetricTensor<2, 3>()
                 : fem::load(old_h, floor_stress_at)
                     + floor * increment.strain_increment;
    response.stress  = from_eigen(sigma) + floor_sigma;
    response.tangent = from_voigt(C) + floor;
    if (!jammed)
      add_jamming_ramp(increment, rho_old, pooled, response);

    for (unsigned int k = 0; k < n_history(); ++k)
      new_h[k] = old_h[k];
    fem::store(response.stress, new_h, stress_at);
    fem::store(floor_sigma, new_h, floor_stress_at);
    new_h[density_at]
      = jammed ? cell.relative_density() : rho_old / volume_ratio;
    // A representative modulus for the contact penalty: the axial entry of
    // the tangent (uniaxial-strain modulus) plus the floor.
    const int axis = static_cast<int>(spec.compaction_axis);
    new_h[modulus_at]
      = (jammed ? std::max(C(axis, axis), 0.0) : template_modulus[pooled]) + Ef;
    new_h[step_at]   = old_h[step_at] + 1.0;
    new_h[jammed_at] = jammed ? 1.0 : 0.0;
    return true;
  }

  void
  RveMaterial::add_jamming_ramp(const fem::MaterialIncrement &increment,
                                const double                  rho_old,
                                const std::size_t             pooled,
                                fem::MaterialResponse        &response) const
  {
    // v = ln(V / V_0) of the increment, a = ln(rho_old / rho_jam) < 0: the
    // trial passes the jamming density when v < a, by the fraction
    // s = 1 - a / v of the increment, which strains the jammed packing.
    const dealii::SymmetricTensor<2, 3> &deps = increment.strain_increment;
    const dealii::SymmetricTensor<2, 3>  stretch
      = dealii::unit_symmetric_tensor<3>() + deps;
    const double v = std::log(dealii::determinant(stretch));
    const double a = std::log(rho_old / template_jamming_density[pooled]);
    if (!(v < a))
      return;
    const double                         s       = 1.0 - a / v;
    const dealii::SymmetricTensor<4, 3> &Ct      = template_tangent[pooled];
    const dealii::SymmetricTensor<2, 3>  Ct_deps = Ct * deps;
    response.stress += s * Ct_deps;
    // d s / d deps = (a / v^2) d v / d deps, d v / d deps = (I + deps)^-1.
    response.tangent
      += s * Ct
         + (a / (v * v))
             * dealii::outer_product(Ct_deps, dealii::invert(stretch));
  }

  dealii::SymmetricTensor<2, 3>
  RveMaterial::stress(dealii::ArrayView<const double> h) const
  {
    return fem::load(h, stress_at);
  }

  double
  RveMaterial::relative_density(dealii::ArrayView<const double> h) const
  {
    return h[density_at];
  }

  dealii::SymmetricTensor<2, 3>
  RveMaterial::plastic_strain(dealii::ArrayView<const double>) const
  {
    return {};
  }

  double
  RveMaterial::youngs_modulus(dealii::ArrayView<const double> h) const
  {
    return h[modulus_at];
  }

  void
  RveMaterial::rotate(dealii::ArrayView<double>   h,
                      const dealii::Tensor<2, 3> &R) const
  {
    fem::store(fem::rotate(fem::load(h, stress_at), R), h, stress_at);
    fem::store(fem::rotate(fem::load(h, floor_stress_at), R),
               h,
               floor_stress_at);
    if (!is_jammed(h))
      return;
    dem::PeriodicBed &cell = trial[static_cast<std::size_t>(h[point_at])];
    dem::map_affinely(cell, to_eigen(R) * cell.deformation);
  }
} // namespace compax::coupling
