#pragma once

#include "fem/material_model.h"

#include <deal.II/base/parameter_handler.h>

#include <memory>

namespace compax::fem
{
  /**
   * Linear isotropic hypoelasticity: sigma_new = sigma_old + C : d_eps with
   * constant Young's modulus and Poisson's ratio. In the small-strain limit
   * it is linear elasticity, which the analytic die tests use. History:
   * stress (6), relative density (1).
   */
  class LinearElasticMaterial : public MaterialModel
  {
  public:
    /// @param youngs_modulus E [Pa] > 0; @param poisson_ratio nu in (-1, 1/2)
    LinearElasticMaterial(double youngs_modulus, double poisson_ratio);

    /// Declares "Young's modulus" and "Poisson's ratio" in the current
    /// subsection (the tablet's Material).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// The material of the entries declare_parameters() declared.
    static std::shared_ptr<const MaterialModel>
    parse_parameters(dealii::ParameterHandler &prm);

    std::string
    name() const override
    {
      return "linear-elastic";
    }

    unsigned int
    n_history() const override
    {
      return 7;
    }

    void
    initialize(double                    relative_density,
               dealii::ArrayView<double> history) const override;

    bool
    evaluate(const MaterialIncrement        &increment,
             dealii::ArrayView<const double> old_history,
             dealii::ArrayView<double>       new_history,
             MaterialResponse               &response) const override;

    dealii::SymmetricTensor<2, 3>
    stress(dealii::ArrayView<const double> history) const override;

    double
    relative_density(dealii::ArrayView<const double> history) const override;

    dealii::SymmetricTensor<2, 3>
    plastic_strain(dealii::ArrayView<const double> history) const override;

    double
    youngs_modulus(dealii::ArrayView<const double> history) const override;

    void
    rotate(dealii::ArrayView<double>   history,
           const dealii::Tensor<2, 3> &R) const override;

  private:
    double                        E;
    dealii::SymmetricTensor<4, 3> C;
  };
} // namespace compax::fem
