#pragma once

#include "dem/contact/contact_law.h"
#include "dem/contact/contact_law_registry.h"
#include "dem/contact/hysteretic_spring.h"

namespace compax::dem
{
  /**
   * Adhesive elasto-plastic multi-contact law of Giannis et al. 2021
   * (Eqs. 6-14): a Luding-type hysteretic law in x = delta^{3/2}, plus a
   * term proportional to the pressure of the two particles.
   *
   * With x = delta^{3/2}, x_max = delta_max^{3/2} and the history variable
   * delta_max (slot 0 of ContactHistory, LargestOverlapHistory):
   * - loading, delta >= delta_max:           F = F_0 + k1 x
   * - un/reloading, delta_min < delta < delta_max:
   *                                          F = F_0 + k2* (x - x_0)
   * - adhesive, 0 < delta <= delta_min:      F = F_0 - kc x
   * - no contact, delta <= 0:                F = 0
   * each plus the multi-contact term beta nu A p (Eq. 13), with
   * - k1 = 4/3 E sqrt(R) (Eq. 2), E the effective modulus WITH the inverse,
   *   E = ((1-nu1^2)/E1 + (1-nu2^2)/E2)^{-1}: the paper prints it without
   *   the inverse (an erratum; see pair_properties.h);
   * - k2*(delta_max) = k1 + (k2 - k1) min(1, delta_max / delta*_max)
   *   (Eq. 11, corrected) and delta*_max = k2/(k2-k1) phi_f 2R (Eq. 12,
   *   2 Ri Rj/(Ri+Rj) = 2R; 2R_i for a rigid wall);
   * - x_0 = (1 - k1/k2*) x_max, i.e.
   *   delta_0 = (1 - k1/k2*)^{2/3} delta_max (Eq. 7, corrected);
   * - x_min = (k2* - k1)/(k2* + kc) x_max, i.e.
   *   delta_min = ((k2* - k1)/(k2* + kc))^{2/3} delta_max (Eq. 9, corrected),
   *   F_min = -kc delta_min^{3/2} (Eq. 8, relative to F_0);
   * - A = pi a^2 with the Hertz contact radius a = sqrt(R delta) (also the
   *   reported contact_radius), so the term is beta nu pi R delta p, and
   *   p = -ContactContext::particle_pressure = -(tr sigma_i + tr sigma_j)/3,
   *   the pressure positive in compression (see the last erratum).
   * The stiffness is the exact dF/ddelta at fixed delta_max and p, i.e.
   * 3/2 k delta^{1/2} of the active branch plus beta nu pi R p.
   *
   * Errata of the printed paper, corrected here from the stated physics
   * (Fig. 3 and the text: the un/reloading branch of slope k2* leaves the
   * loading branch at delta_max, reaches zero force at the plastic overlap
   * delta_0, and meets the adhesive branch -kc x at delta_min):
   * - Eq. (7) gives delta_0 with k2; continuity with the loading branch at
   *   delta_max, k2* (x_max - x_0) = k1 x_max, needs k2*:
   *   delta_0 = (1 - k1/k2*)^{2/3} delta_max. (Same for the case test of
   *   the first line of Eqs. 6 and 14, printed with k2: with k2* it reads
   *   delta >= delta_max.)
   * - Eq. (9) gives delta_min = ((k2 - k1)/(k2 - kc))^{2/3} delta_max; the
   *   crossing k2* (x - x_0) = -kc x gives
   *   x_min = k2* x_0 / (k2* + kc), i.e. (k2* - k1)/(k2* + kc) with a PLUS
   *   sign on kc (as in Luding's linear model) and k2* for k2.
   * - Eq. (11) prints k1 + (k2 - k1) delta*_max / delta_max for
   *   delta_max < delta*_max, which exceeds k2 and diverges as
   *   delta_max -> 0, against Fig. 3 ("k2* interpolates between k1 and a
   *   maximum stiffness k2") and Luding's model that it follows: the ratio is
   *   delta_max / delta*_max.
   * - Eq. (13) adds beta nu A P_ij with P_ij = (tr sigma_i + tr sigma_j)/3
   *   and calls it a pressure; the term is meant to stiffen confined
   *   contacts (Figs. 8-9: beta = 0 underestimates the stress), so P_ij must
   *   be positive in compression. ContactContext stores it positive in
   *   tension, hence p = -particle_pressure here.
   * Remarks (not corrected): with x = delta^{3/2}, Eq. (12) no longer gives
   * delta_0 = phi_f 2R at delta_max = delta*_max as in Luding's linear model
   * but (1 - k1/k2)^{-1/3} phi_f 2R. The history is delta_max only, so
   * reloading from the adhesive branch retraces it and the un/reloading
   * branch (no separate reloading path). A nonzero F_0 makes the force jump
   * by F_0 at delta = 0 (contact made or lost).
   */
  class MulticontactAdhesiveLaw final : public ContactLaw,
                                        public LargestOverlapHistory
  {
  public:
    /// Dimensionless parameters of the law (Giannis 2021, Table 3) and F_0.
    struct Parameters
    {
      /// k2/k1 >= 1 [-], the largest un/reloading stiffness (paper: 120).
      double unloading_stiffness_ratio = 1.0;
      /// kc/k1 >= 0 [-], the adhesive branch stiffness (paper: 0.5).
      double adhesion_stiffness_ratio = 0.0;
      /// phi_f >= 0 [-], plasticity depth relative to 2R (paper: 0.99).
      double plasticity_depth = 0.0;
      /// beta [-], prefactor of the multi-contact term (paper: 1.3, 1.5).
      double multicontact_prefactor = 0.0;
      /// F_0 [N], constant pull-off force added while in contact; negative
      /// is attractive.
      double pull_off_force = 0.0;
      /// nu [-], Poisson's ratio of the multi-contact term.
      double poisson_ratio = 0.0;
    };

    /// @param effective_radius R = (1/R1 + 1/R2)^{-1} [m]
    /// @param effective_modulus E = ((1-nu1^2)/E1 + (1-nu2^2)/E2)^{-1} [Pa]
    MulticontactAdhesiveLaw(double            effective_radius,
                            double            effective_modulus,
                            const Parameters &parameters);

    /// Law of two spheres given their radii and elastic constants; pass
    /// compax::dem::rigid for the radius and modulus of a wall.
    static MulticontactAdhesiveLaw
    for_pair(double            R1,
             double            E1,
             double            nu1,
             double            R2,
             double            E2,
             double            nu2,
             const Parameters &parameters);

    /// Needs the particle pressure P_ij: the explicit DEM evaluates it,
    /// not the static particle solvers.
    static constexpr bool needs_context = true;

    /// The law's parameters and builder for the command line
    /// (contact_law_registry.h).
    static RegisteredContactLaw
    registration();

    /// delta_max [m].
    std::vector<HistoryVariable>
    history_variables() const override
    {
      return variables();
    }

    using ContactLaw::evaluate;
    using ContactLaw::updated_history;

    ContactResponse
    evaluate(double                gamma,
             const ContactHistory &history,
             const ContactContext &context) const override;

    /// delta_max <- max(delta_max, gamma); the other slot is left untouched.
    ContactHistory
    updated_history(double                gamma,
                    const ContactHistory &history,
                    const ContactContext &context) const override;

    std::string
    name() const override
    {
      return "multicontact-adhesive";
    }

    /// Force, stiffness and radius at overlap delta [m] for the largest
    /// overlap delta_max [m] and particle pressure P_ij [Pa] (positive in
    /// tension, as ContactContext), without virtual dispatch.
    ContactResponse
    response(double delta, double delta_max, double particle_pressure) const;

    /// k1 = 4/3 E sqrt(R) [N/m^{3/2}].
    double
    loading_stiffness() const
    {
      return k1;
    }

    /// k2* (delta_max) [N/m^{3/2}] (Eq. 11, corrected).
    double
    unloading_stiffness(double delta_max) const;

    /// delta*_max [m] (Eq. 12); infinite when k2 = k1.
    double
    plastic_flow_limit() const;

    /// Plastic overlap delta_0 [m] (Eq. 7, corrected).
    double
    plastic_overlap(double delta_max) const;

    /// Overlap delta_min [m] where un/reloading meets the adhesive branch
    /// (Eq. 9, corrected).
    double
    minimum_overlap(double delta_max) const;

    /// F_min = -kc delta_min^{3/2} [N] (Eq. 8), relative to F_0 and without
    /// the multi-contact term.
    double
    minimum_force(double delta_max) const;

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

    const Parameters &
    parameters() const
    {
      return p;
    }

  private:
    /// The branches in x = delta^{3/2}.
    HystereticSpring
    spring() const
    {
      return {k1, k2, kc};
    }

    double     R;
    double     E;
    Parameters p;
    double     k1;
    double     k2;
    double     kc;
    /// beta nu pi R [m]: the multi-contact force per overlap and pressure.
    double multicontact_factor;
  };
} // namespace compax::dem
