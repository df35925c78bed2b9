#pragma once

#include "fem/dpc_table.h"
#include "fem/material_model.h"

#include <deal.II/base/parameter_handler.h>

#include <memory>

namespace compax::fem
{
  /**
   * Density-dependent Drucker-Prager Cap (DPC) plasticity in the form
   * pharmaceutical FE studies use (Abaqus' DPC without transition surface,
   * alpha = 0; Han et al. 2008), with p = -tr(sigma)/3 and
   * q = sqrt(3 J2):
   *  - shear failure  F_s = q - p tan(beta) - d <= 0 for p <= p_a,
   *  - cap            F_c = sqrt((p - p_a)^2 + (R q)^2) - R (d + p_a tan(beta))
   *                   <= 0 for p >= p_a, with
   *    p_a = (p_b - R d) / (1 + R tan(beta)).
   * The cap hardens with the plastic volumetric compaction through the
   * "plastic density" rho_p (rho_p,new = rho_p,old exp(d eps_v^p)), p_b =
   * p_b(rho_p) from the table; d, beta, R, E, nu follow the current
   * relative density at the start of the increment (explicit in density,
   * so the return mapping and its tangent stay exact for the increment).
   * Flow: associated on both surfaces (a symmetric tangent and a stable
   * increment problem; a non-associated potential on the shear line, as in
   * Abaqus, made Newton stall where the rim of the tablet fails as it
   * leaves the die). The shear line therefore dilates, which lowers the
   * plastic density and shrinks the cap. The corner p = p_a is a
   * two-surface return; tension beyond the apex returns to the apex, whose
   * zero tangent is replaced by a tenth of the elastic one.
   * Elasticity is isotropic hypoelastic with K, G of the current density.
   *
   * History: stress (6), relative density (1), plastic strain (6), plastic
   * density (1).
   */
  class DruckerPragerCap : public MaterialModel
  {
  public:
    explicit DruckerPragerCap(DpcTable table);

    /// Declares "DPC table" (a CSV file, empty: the built-in
    /// microcrystalline cellulose) in the current subsection.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// The material of the table declare_parameters() names; a file that
    /// cannot be read or is not a DPC table is an input::InputError
    /// naming Material/DPC table.
    static std::shared_ptr<const MaterialModel>
    parse_parameters(dealii::ParameterHandler &prm);

    std::string
    name() const override
    {
      return "drucker-prager-cap";
    }

    unsigned int
    n_history() const override
    {
      return 14;
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

    /// The plastic density rho_p [-] that sets the cap.
    double
    plastic_density(dealii::ArrayView<const double> history) const
    {
      return history[13];
    }

    /**
     * Value of the active yield function [Pa] of @p stress for the
     * parameters of relative density @p rho and the cap of plastic density
     * @p rho_p: F_s for p <= p_a, F_c otherwise (<= 0 inside).
     */
    double
    yield_function(const dealii::SymmetricTensor<2, 3> &stress,
                   double                               rho,
                   double                               rho_p) const;

    /// p_a [Pa] of the cap for the parameters of @p rho and plastic
    /// density @p rho_p.
    double
    cap_transition_pressure(double rho, double rho_p) const;

    const DpcTable &
    table() const
    {
      return data;
    }

  private:
    DpcTable data;
  };
} // namespace compax::fem
