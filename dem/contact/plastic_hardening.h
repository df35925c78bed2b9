#pragma once

#include "dem/contact/bonded_elastoplastic.h"
#include "dem/contact/contact_law_registry.h"
#include "dem/contact/history_free_law.h"

namespace compax::dem
{
  /**
   * Spheres with power-law hardening plastic behaviour and no elastic
   * unloading, no solid bridge: the plastic loading branch of Gonzalez
   * 2018, Eqs. (1)-(2), P = n_p a^{2+1/m} with a^2 = 2 c^2 R gamma, at every
   * overlap gamma > 0, so that unloading retraces loading and the law keeps
   * no internal variables. This is the comparison Gonzalez 2018 §5.1 draws
   * for K_Ic = 0 ("the jamming transition occurs later for K_Ic = 0, cf.
   * Gonzalez et al. (2018)"): that reference (Mech. Res. Commun. 92:131)
   * studies "particles with hardening plastic behavior, but no elastic
   * unloading and formation of bonding strength" (§6), on our reading this
   * law, not the bonded law with K_Ic = 0, which unloads elastically.
   *
   * The branch is the bonded law's own at a fresh contact (a_p = 0, which
   * is plastic loading at every gamma > 0), so both share n_p, c^2 and the
   * mixing rules; the stiffness is that branch's exact dP/dgamma.
   */
  class PlasticHardeningLaw final : public HistoryFreeLaw<PlasticHardeningLaw>
  {
  public:
    /// The plastic constants of both bodies: kappa [Pa] and m [-].
    struct Parameters
    {
      double plastic_stiffness = 0.0;
      double plastic_exponent  = 1.0;
    };

    /// Law between spheres of radii R1 and R2 [m] of one material; pass
    /// compax::dem::rigid for R2 of a flat wall (rigid: kappa infinite).
    /// Throws std::invalid_argument unless kappa > 0 and m >= 1.
    static PlasticHardeningLaw
    for_pair(double R1, double R2, const Parameters &parameters);

    /// The law's parameters with their ranges and units, and its builder,
    /// for the command line (contact_law_registry.h).
    static RegisteredContactLaw
    registration();

    std::string
    name() const override
    {
      return "plastic-hardening";
    }

    /// Force, stiffness and radius of the plastic loading branch at
    /// overlap gamma [m]; nothing for gamma <= 0.
    ContactResponse
    response(double gamma) const
    {
      return loading.response(gamma, 0.0, 0.0);
    }

    /// n_p [N/m^{2+1/m}] of the pair (Gonzalez 2018, after Eq. 1).
    double
    plastic_coefficient() const
    {
      return loading.constants().plastic_coefficient;
    }

  private:
    explicit PlasticHardeningLaw(const BondedElastoplasticLaw &branch);

    /// The bonded law without a bridge, evaluated at a_p = 0 only.
    BondedElastoplasticLaw loading;
  };
} // namespace compax::dem
