#pragma once

#include "dem/contact/contact_law.h"
#include "dem/contact/elastoplastic_material.h"

#include <cmath>

namespace compax::dem
{
  /**
   * Loading-unloading law of elasto-plastic spheres that form solid bridges
   * (Gonzalez 2018, Eqs. 3-5 and 13, after Mesarovic & Johnson 2000).
   *
   * Plastic loading (gamma >= gamma_p): a^2 = 2 c^2 R gamma and
   * P = n_p a^{2+1/m}. Elastic (un)loading (gamma < gamma_p):
   * a^2 = [a_p^2 - (4 E (gamma_p - gamma) / (3 n_p a_p^{1/m}))^2]_+ and
   * P = 2 n_p/pi a_p^{2+1/m} [asin(a/a_p) - a/a_p sqrt(1 - (a/a_p)^2)]
   *     - 2 K_Ic sqrt(pi) a^{3/2} (1+xi_B)^2 [a_B - a]_+ / ((1+xi_B) a_B - a).
   * The internal variables are the plastic contact radius a_p (with
   * gamma_p = a_p^2 / 2 c^2 R) and the bonded radius a_B.
   *
   * The exact stiffness of the elastic part simplifies to
   * dP/dgamma = 16 E a / (3 pi), the value Eq. (8) factors out.
   *
   * Errata of the printed paper, corrected here:
   * - After Eq. (2) the force is said to act along (x1 - x2)/|x1 - x2| on
   *   particle 2; Eq. (12) and physics (P > 0 repulsive) need the opposite:
   *   on particle i the force is P (x_i - x_j)/|x_i - x_j|.
   * - Eq. (12) lists a_B twice among the arguments of P; P depends on
   *   (a, a_p, a_B) only.
   * - Sec. 3.1 states chi = 0.0493 for the Du et al. case. With the
   *   definition chi = 4 pi K_Ic^2 / (n_p^2 a_p^{1+2/m}) and a_p at
   *   gamma_max = 28.2 nm, neither geometric convention gives it: a sphere
   *   on a rigid flat (the finite-element model, and compax's sphere-wall
   *   convention) gives chi = 0.0427, two identical spheres 0.0889
   *   (tests/unit/test_bonded_elastoplastic.cc computes both).
   *
   * The unregularized law of Eq. (2) is the limit xi_B = 0, selected by
   * `regularized = false`: its force jumps by 2 K_Ic sqrt(pi) a_p^{3/2} at
   * the onset of unloading.
   */
  class BondedElastoplasticLaw final : public ContactLaw
  {
  public:
    /// Constants of one pair, all in SI units.
    struct PairConstants
    {
      /// Effective radius R [m].
      double effective_radius;
      /// Effective plane-strain modulus E [Pa].
      double effective_modulus;
      /// Plastic law exponent m [-], common to both bodies.
      double plastic_exponent;
      /// Plastic law coefficient n_p [N/m^{2+1/m}].
      double plastic_coefficient;
      /// Fracture toughness of the solid bridge K_Ic [Pa m^{1/2}]; 0 for no
      /// bonding.
      double fracture_toughness;
      /// Regularization parameter xi_B > 0 [-] (used when regularized).
      double regularization;
      /// Eq. (4) when true; the discontinuous Eq. (2) when false.
      bool regularized = true;
    };

    explicit BondedElastoplasticLaw(const PairConstants &constants);

    /**
     * Law between two spheres of radii R1, R2 (compax::dem::rigid for a flat
     * wall) and materials with the same plastic exponent m.
     */
    static BondedElastoplasticLaw
    for_pair(const ElastoplasticMaterial &material1,
             double                       R1,
             const ElastoplasticMaterial &material2,
             double                       R2,
             double                       fracture_toughness,
             double                       regularization,
             bool                         regularized = true);

    /// Slots of the internal variables in ContactHistory.
    static constexpr std::size_t a_p_slot = 0;
    static constexpr std::size_t a_B_slot = 1;

    /// Plastic contact radius a_p [m] of a contact's history.
    static double
    a_p(const ContactHistory &history)
    {
      return history[a_p_slot];
    }

    /// Radius of the bonded area a_B [m] of a contact's history.
    static double
    a_B(const ContactHistory &history)
    {
      return history[a_B_slot];
    }

    /// The history of plastic radius a_p and bonded radius a_B [m].
    static ContactHistory
    history(double a_p, double a_B);

    /// a_p and a_B, both [m].
    std::vector<HistoryVariable>
    history_variables() const override
    {
      return {{"a_p", "plastic_radius", "m"}, {"a_B", "bond_radius", "m"}};
    }

    /// a_B > 0: the contact holds a solid bridge.
    bool
    bonded(const ContactHistory &history) const override
    {
      return a_B(history) > 0.0;
    }

    using ContactLaw::evaluate;
    using ContactLaw::updated_history;

    ContactResponse
    evaluate(double                gamma,
             const ContactHistory &history,
             const ContactContext &context) const override;

    /// Eq. (13): plastic loading and bond formation when a > a_p, bond
    /// breakage when a = 0, unchanged otherwise.
    ContactHistory
    updated_history(double                gamma,
                    const ContactHistory &history,
                    const ContactContext &context) const override;

    /// 16 E a / (3 pi) where the contact loads plastically (a >= a_p > 0
    /// or virgin), the law's stiffness elsewhere.
    double
    unloading_stiffness(double                gamma,
                        const ContactHistory &history,
                        const ContactContext &context) const override;

    /// a(gamma) > a_p: Eq. (13) would grow the plastic radius.
    bool
    loads_plastically(double                gamma,
                      const ContactHistory &history,
                      const ContactContext &context) const override;

    /// -breakage_overlap(a_p) where that is a separation, else 0: the
    /// contact radius, and with it the force, vanishes below the breakage
    /// overlap, bridge or none.
    double
    separation_reach(const ContactHistory &history,
                     const ContactContext &context) const override;

    std::string
    name() const override
    {
      return "bonded-elastoplastic";
    }

    /// Force, stiffness and radius without virtual dispatch.
    ContactResponse
    response(double gamma, double a_p, double a_B) const;

    /// Contact radius a(gamma; a_p) of Eq. (3) [m].
    double
    contact_radius(double gamma, double a_p) const;

    /// Plastic overlap gamma_p = a_p^2 / (2 c^2 R) [m].
    double
    plastic_overlap(double a_p) const;

    /// Plastic contact radius reached by plastic loading to gamma [m].
    double
    plastic_radius(double gamma) const;

    /// Overlap at which a bridge of plastic radius a_p breaks on unloading,
    /// gamma_p - 3 n_p a_p^{1+1/m} / (4 E) [m] (Sec. 3).
    double
    breakage_overlap(double a_p) const;

    /// Ratio of bonding to stored elastic energy
    /// chi = 4 pi K_Ic^2 / (n_p^2 a_p^{1+2/m}) [-] (Sec. 3.1).
    double
    bonding_energy_ratio(double a_p) const;

    /// c^2 = 1.43 exp(-0.97/m) [-].
    double
    c_squared() const
    {
      return c2;
    }

    const PairConstants &
    constants() const
    {
      return k;
    }

  private:
    /// x^{1/m}, by sqrt for m = 2 (libm's pow dominated the profile of
    /// the residual; the solvers evaluate response() in their hot loops).
    double
    root_m(const double x) const
    {
      return k.plastic_exponent == 2.0 ? std::sqrt(x) : std::pow(x, inverse_m);
    }

    PairConstants k;
    double        c2;
    double        inverse_m;
  };
} // namespace compax::dem
