#include "fem/linear_elastic_material.h"

#include "fem/isotropic_elasticity.h"
#include "input/parameter_declaration.h"
#include "input/real_interval.h"

namespace compax::fem
{
  LinearElasticMaterial::LinearElasticMaterial(const double youngs_modulus,
                                               const double poisson_ratio)
      : E(youngs_modulus)
      , C(isotropic_stiffness_tensor(youngs_modulus, poisson_ratio))
  {
  }

  void
  LinearElasticMaterial::declare_parameters(dealii::ParameterHandler &prm)
  {
    input::declare_quantity(prm,
                            "Young's modulus",
                            "5e9",
                            input::positive(),
                            "Pa",
                            "Young's modulus of the linear-elastic model.");
    input::declare_quantity(prm,
                            "Poisson's ratio",
                            "0.3",
                            input::open(-1.0, 0.5),
                            "-",
                            "Poisson's ratio of the linear-elastic model.");
  }

  std::shared_ptr<const MaterialModel>
  LinearElasticMaterial::parse_parameters(dealii::ParameterHandler &prm)
  {
    return std::make_shared<LinearElasticMaterial>(
      prm.get_double("Young's modulus"), prm.get_double("Poisson's ratio"));
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
