#pragma once

#include "dem/contact/contact_law.h"
#include "dem/contact/contact_law_registry.h"
#include "dem/contact/hysteretic_spring.h"

namespace compax::dem
{
  /**
   * The hysteretic linear spring of Walton & Braun (1986) in Luding's form
   * (Luding 2008, Granular Matter 10:235), the normal law that the
   * explicit-DEM peer LIGGGHTS runs as `hooke/hysteresis`: a plastic
   * loading branch of stiffness k1, an elastic un/reloading branch whose
   * stiffness k2 rises with the largest overlap, and an optional adhesive
   * branch of stiffness kc. With the history variable delta_max
   * (slot 0 of ContactHistory, LargestOverlapHistory), the largest overlap of a
   * converged state:
   * - loading, delta >= delta_max:               F = k1 delta
   * - un/reloading, delta_min < delta < delta_max: F = k2 (delta - delta_0)
   * - adhesive, 0 < delta <= delta_min:           F = -kc delta
   * - no contact, delta <= 0:                     F = 0
   * with
   * - k2(delta_max) = k1 + (k2_max - k1) min(1, delta_max / delta*), the
   *   plastic flow limit delta* = k2_max / (k2_max - k1) phi_F 2R, where R
   *   is the effective radius (2R = 2 R_i R_j / (R_i + R_j) of a pair,
   *   2 R_i against a rigid wall);
   * - the plastic overlap delta_0 = (1 - k1/k2) delta_max, where the
   *   un/reloading branch, continuous with the loading one at delta_max,
   *   carries no force;
   * - delta_min = (k2 - k1) / (k2 + kc) delta_max, where it meets the
   *   adhesive branch (delta_min = delta_0 for kc = 0: the contact then
   *   carries nothing below delta_0).
   * The stiffness is the exact dF/ddelta at fixed delta_max. A linear
   * spring has no contact radius; contact_radius reports the geometric
   * sqrt(R delta).
   */
  class WaltonBraunLaw final : public ContactLaw, public LargestOverlapHistory
  {
  public:
    struct Parameters
    {
      /// k1 > 0 [N/m], the plastic loading stiffness.
      double loading_stiffness = 0.0;
      /// k2_max / k1 >= 1 [-], the largest un/reloading stiffness.
      double unloading_stiffness_ratio = 1.0;
      /// kc / k1 >= 0 [-], the adhesive branch (0: no adhesion).
      double adhesion_stiffness_ratio = 0.0;
      /// phi_F >= 0 [-], the plasticity depth relative to 2R.
      double plasticity_depth = 0.0;
    };

    /// @param effective_radius R = (1/R1 + 1/R2)^{-1} [m]
    WaltonBraunLaw(double effective_radius, const Parameters &parameters);

    /// Law of two spheres of radii R1 and R2 [m]; pass compax::dem::rigid
    /// for a wall.
    static WaltonBraunLaw
    for_pair(double R1, double R2, const Parameters &parameters);

    /// A local law: the particle solvers may hold it (particle_law.h).
    static constexpr bool needs_context = false;

    /// The law's parameters with their ranges and units, and its builder,
    /// for the command line (contact_law_registry.h).
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

    /// The branch the contact unloads along: k2(gamma) where it loads
    /// (gamma >= delta_max), else the stiffness of its current branch.
    double
    unloading_stiffness(double                gamma,
                        const ContactHistory &history,
                        const ContactContext &context) const override;

    /// Loading beyond the largest overlap, gamma > max(delta_max, 0).
    bool
    loads_plastically(double                gamma,
                      const ContactHistory &history,
                      const ContactContext &context) const override;

    /// 0: every branch, the adhesive one included, ends at contact.
    double
    separation_reach(const ContactHistory &,
                     const ContactContext &) const override
    {
      return 0.0;
    }

    std::string
    name() const override
    {
      return "walton-braun";
    }

    /// Force, stiffness and radius at overlap delta [m] for the largest
    /// overlap delta_max [m], without virtual dispatch.
    ContactResponse
    response(double delta, double delta_max) const;

    /// k2(delta_max) [N/m].
    double
    unloading_stiffness(double delta_max) const;

    /// delta* [m]; infinite when k2_max = k1.
    double
    plastic_flow_limit() const;

    /// delta_0 [m], where un/reloading carries no force.
    double
    plastic_overlap(double delta_max) const;

    /// delta_min [m], where un/reloading meets the adhesive branch.
    double
    minimum_overlap(double delta_max) const;

    double
    effective_radius() const
    {
      return R;
    }

    const Parameters &
    parameters() const
    {
      return p;
    }

  private:
    double           R;
    Parameters       p;
    HystereticSpring spring;
  };
} // namespace compax::dem
