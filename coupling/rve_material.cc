#include "coupling/rve_material.h"

#include "dem/rve/periodic_bed_system.h"
#include "fem/isotropic_elasticity.h"

#include <cmath>

namespace compax::coupling
{
  namespace
  {
    // History layout.
    constexpr unsigned int stress_at = 0, density_at = 6, modulus_at = 7,
                           floor_stress_at = 8, point_at = 14, step_at = 15;

    constexpr int voigt_i[6] = {0, 1, 2, 1, 0, 0};
    constexpr int voigt_j[6] = {0, 1, 2, 2, 2, 1};

    Eigen::Matrix3d
    to_eigen(const dealii::Tensor<2, 3> &t)
    {
      Eigen::Matrix3d m;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          m(i, j) = t[i][j];
      return m;
    }

    Eigen::Matrix3d
    to_eigen(const dealii::SymmetricTensor<2, 3> &t)
    {
      Eigen::Matrix3d m;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          m(i, j) = t[i][j];
      return m;
    }

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

  RveMaterial::RveMaterial(RveMaterialSpec spec, dem::ContactModel model)
      : spec(std::move(spec))
      , model(std::move(model))
      , newton(this->spec.loading.equilibrium)
  {
  }

  void
  RveMaterial::initialize(const double rho, dealii::ArrayView<double> h) const
  {
    if (templates.empty() || template_density != rho)
      {
        templates.clear();
        for (unsigned int k = 0; k < spec.pool_size; ++k)
          {
            dem::PeriodicPackingSpec p = spec.packing;
            p.relative_density         = rho;
            p.seed                     = spec.packing.seed + k;
            templates.push_back(dem::make_periodic_packing(p, model));
          }
        template_density = rho;
      }
    const std::size_t point = committed.size();
    committed.push_back(templates[point % templates.size()]);
    trial.push_back(committed.back());
    committed_steps.push_back(0.0);
    for (double &v : h)
      v = 0.0;
    h[density_at] = committed.back().relative_density();
    h[modulus_at] = spec.tangent_floor_modulus;
    h[point_at]   = static_cast<double>(point);
    h[step_at]    = 0.0;
  }

  void
  RveMaterial::catch_up(const std::size_t point,
                        const double      committed_step) const
  {
    if (committed_step == committed_steps[point] + 1.0)
      {
        dem::PeriodicBed &cell = trial[point];
        cell.contacts.update_histories(cell.particles, cell.cell);
        committed[point]       = cell;
        committed_steps[point] = committed_step;
      }
  }

  bool
  RveMaterial::evaluate(const fem::MaterialIncrement   &increment,
                        dealii::ArrayView<const double> old_h,
                        dealii::ArrayView<double>       new_h,
                        fem::MaterialResponse          &response) const
  {
    const auto point = static_cast<std::size_t>(old_h[point_at]);
    catch_up(point, old_h[step_at]);

    dem::PeriodicBed &cell = trial[point];
    cell                   = committed[point];
    const Eigen::Matrix3d stretch
      = Eigen::Matrix3d::Identity() + to_eigen(increment.strain_increment);
    dem::map_affinely(cell, stretch * cell.deformation);
    dem::PeriodicBedSystem system(cell, model, assembler);
    // Below jamming (judged on the committed cell, so within a step the
    // branch does not change) the cell rearranges by FIRE with frozen
    // histories and carries no stress to speak of: its stress and tangent
    // are taken as zero, which keeps the response smooth for the continuum
    // Newton (FIRE's relaxed stress is noise at the level of its
    // tolerance). Once jammed: Newton equilibrium, Love-Weber stress and
    // condensed tangent.
    const bool jammed
      = dem::mean_pressure(committed[point]) >= spec.loading.jamming_pressure;
    Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
    dem::Matrix6d   C     = dem::Matrix6d::Zero();
    if (jammed)
      {
        if (!newton.solve(system).converged)
          return false;
        sigma = dem::love_weber_stress(cell);
        C     = tangent.compute(cell, model).condensed;
      }
    else
      {
        const double R = cell.particles.mean_radius();
        fire.relax(system,
                   spec.loading.fire_tolerance,
                   spec.loading.fire_iterations,
                   spec.loading.force_floor_fraction
                     * spec.loading.jamming_pressure * M_PI * R * R);
      }

    // The floor is a weak hypoelastic skeleton in parallel with the RVE:
    // its stress is integrated like any hypoelastic law's, so that stress
    // and tangent stay consistent.
    const double                        Ef = spec.tangent_floor_modulus;
    const dealii::SymmetricTensor<4, 3> floor
      = fem::isotropic_stiffness_tensor(Ef, 0.25);
    const dealii::SymmetricTensor<2, 3> floor_stress
      = fem::load(old_h, floor_stress_at) + floor * increment.strain_increment;
    response.stress  = from_eigen(sigma) + floor_stress;
    response.tangent = from_voigt(C) + floor;

    for (unsigned int k = 0; k < n_history(); ++k)
      new_h[k] = old_h[k];
    fem::store(response.stress, new_h, stress_at);
    fem::store(floor_stress, new_h, floor_stress_at);
    new_h[density_at] = cell.relative_density();
    // A representative modulus for the contact penalty: the axial entry of
    // the tangent (uniaxial-strain modulus) plus the floor.
    new_h[modulus_at] = std::max(C(2, 2), 0.0) + Ef;
    new_h[step_at]    = old_h[step_at] + 1.0;
    return true;
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
    dem::PeriodicBed &cell = trial[static_cast<std::size_t>(h[point_at])];
    dem::map_affinely(cell, to_eigen(R) * cell.deformation);
  }
} // namespace compax::coupling
