#include "fem/linear_elastic_material.h"

#include "fem/isotropic_elasticity.h"

namespace compax::fem
{
  LinearElasticMaterial::LinearElasticMaterial(const double youngs_modulus,
                                               const double poisson_ratio)
      : E(youngs_modulus)
      , C(isotropic_stiffness_tensor(youngs_modulus, poisson_ratio))
  {
  }

  void
  LinearElasticMaterial::initialize(const double              rho,
                                    dealii::ArrayView<double> h) const
  {
    store(dealii::SymmetricTensor<2, 3>(), h, 0);
    h[6] = rho;
  }

  bool
  LinearElasticMaterial::evaluate(const MaterialIncrement        &inc,
                                  dealii::ArrayView<const double> old_h,
                                  dealii::ArrayView<double>       new_h,
                                  MaterialResponse               &r) const
  {
    r.stress  = load(old_h, 0) + C * inc.strain_increment;
    r.tangent = C;
    store(r.stress, new_h, 0);
    new_h[6] = old_h[6] / dealii::determinant(inc.deformation_increment);
    return true;
  }

  dealii::SymmetricTensor<2, 3>
  LinearElasticMaterial::stress(dealii::ArrayView<const double> h) const
  {
    return load(h, 0);
  }

  double
  LinearElasticMaterial::relative_density(
    dealii::ArrayView<const double> h) const
  {
    return h[6];
  }

  dealii::SymmetricTensor<2, 3>
  LinearElasticMaterial::plastic_strain(dealii::ArrayView<const double>) const
  {
    return {};
  }

  double
  LinearElasticMaterial::youngs_modulus(dealii::ArrayView<const double>) const
  {
    return E;
  }

  void
  LinearElasticMaterial::rotate(dealii::ArrayView<double>   h,
                                const dealii::Tensor<2, 3> &R) const
  {
    store(fem::rotate(load(h, 0), R), h, 0);
  }
} // namespace compax::fem
