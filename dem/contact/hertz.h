#pragma once

#include "dem/contact/contact_law_registry.h"
#include "dem/contact/history_free_law.h"

#include <cmath>

namespace compax::dem
{
  /**
   * Hertz contact of two elastic spheres, or of a sphere on a rigid flat:
   * P = n_H gamma^{3/2} with n_H = 4/3 E sqrt(R) and contact radius
   * a = sqrt(R gamma), for gamma > 0; no force otherwise (Johnson 1985,
   * Sec. 4.2; Gonzalez & Cuitino 2012, Eq. 9 with gamma_NL = 0).
   */
  class HertzLaw final : public HistoryFreeLaw<HertzLaw>
  {
  public:
    /// @param effective_radius R = (1/R1 + 1/R2)^{-1} [m]
    /// @param effective_modulus E = ((1-nu1^2)/E1 + (1-nu2^2)/E2)^{-1} [Pa]
    HertzLaw(double effective_radius, double effective_modulus);

    /// Hertz law of two spheres given their radii and elastic constants;
    /// pass compax::dem::rigid for the radius and modulus of a wall.
    static HertzLaw
    for_pair(double R1,
             double E1,
             double nu1,
             double R2,
             double E2,
             double nu2);

    /// The law's parameters and builder for the command line
    /// (contact_law_registry.h).
    static RegisteredContactLaw
    registration();

    std::string
    name() const override
    {
      return "hertz";
    }

    /// Force, stiffness and radius of the pure Hertz law at overlap gamma
    /// (inline: the nonlocal fixed point evaluates it in every sweep).
    ContactResponse
    response(const double gamma) const
    {
      if (gamma <= 0.0)
        return {};
      const double root = std::sqrt(gamma);
      return {n_H * gamma * root, 1.5 * n_H * root, std::sqrt(R * gamma)};
    }

    /// The Hertz coefficient n_H = 4/3 E sqrt(R) [N/m^{3/2}].
    double
    coefficient() const
    {
      return n_H;
    }

    double
    effective_radius() const
    {
      return R;
    }

    double
    effective_modulus() const
    {
      return E;
    }

  private:
    double R;
    double E;
    double n_H;
  };
} // namespace compax::dem
