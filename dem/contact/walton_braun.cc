#include "dem/contact/walton_braun.h"

#include "dem/contact/pair_properties.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace compax::dem
{
  WaltonBraunLaw::WaltonBraunLaw(const double      effective_radius,
                                 const Parameters &parameters)
      : R(effective_radius)
      , p(parameters)
      , spring{parameters.loading_stiffness,
               parameters.unloading_stiffness_ratio
                 * parameters.loading_stiffness,
               parameters.adhesion_stiffness_ratio
                 * parameters.loading_stiffness}
  {
    if (!(parameters.loading_stiffness > 0.0))
      throw std::invalid_argument("walton-braun: k1 must be positive");
    if (!(parameters.unloading_stiffness_ratio >= 1.0))
      throw std::invalid_argument("walton-braun: k2/k1 must be at least 1");
    if (!(parameters.adhesion_stiffness_ratio >= 0.0))
      throw std::invalid_argument("walton-braun: kc/k1 must not be negative");
    if (!(parameters.plasticity_depth >= 0.0))
      throw std::invalid_argument("walton-braun: phi_F must not be negative");
  }

  WaltonBraunLaw
  WaltonBraunLaw::for_pair(const double      R1,
                           const double      R2,
                           const Parameters &parameters)
  {
    return WaltonBraunLaw(dem::effective_radius(R1, R2), parameters);
  }

  RegisteredContactLaw
  WaltonBraunLaw::registration()
  {
    const double         inf = std::numeric_limits<double>::infinity();
    RegisteredContactLaw r;
    r.name        = "walton-braun";
    r.description = "the hysteretic linear spring of Walton & Braun and "
                    "Luding (LIGGGHTS' hooke/hysteresis)";
    r.subsection  = "Walton-Braun";
    r.parameters
      = {{"Loading stiffness",
          6.09e4,
          0.0,
          true,
          inf,
          true,
          "N/m",
          "k1 > 0: the plastic loading stiffness (6.09e4 N/m: the "
          "explicit-DEM peer's pair value for Material 1, "
          "../shared/peer/README.md)."},
         {"Unloading stiffness ratio",
          22.0,
          1.0,
          false,
          1e12,
          false,
          "-",
          "k2_max/k1 >= 1: the largest un/reloading stiffness over k1."},
         {"Adhesion stiffness ratio",
          0.0,
          0.0,
          false,
          inf,
          true,
          "-",
          "kc/k1 >= 0: the adhesive branch (0: no adhesion)."},
         {"Plasticity depth",
          0.573,
          0.0,
          false,
          inf,
          true,
          "-",
          "phi_F >= 0: plasticity depth relative to 2R; the un/reloading "
          "stiffness reaches k2_max at the overlap k2_max/(k2_max - k1) "
          "phi_F 2R."}};
    r.make = [](const LawParameterValues &v, const ContactBodies &b) {
      Parameters p;
      p.loading_stiffness         = v.at("Loading stiffness");
      p.unloading_stiffness_ratio = v.at("Unloading stiffness ratio");
      p.adhesion_stiffness_ratio  = v.at("Adhesion stiffness ratio");
      p.plasticity_depth          = v.at("Plasticity depth");
      return std::make_unique<WaltonBraunLaw>(for_pair(b.R1, b.R2, p));
    };
    return r;
  }

  double
  WaltonBraunLaw::plastic_flow_limit() const
  {
    return spring.plastic_flow_limit(p.plasticity_depth, R);
  }

  double
  WaltonBraunLaw::unloading_stiffness(const double delta_max) const
  {
    return spring.unloading_stiffness(std::max(delta_max, 0.0),
                                      plastic_flow_limit());
  }

  double
  WaltonBraunLaw::plastic_overlap(const double delta_max) const
  {
    if (delta_max <= 0.0)
      return 0.0;
    return (1.0 - spring.k1 / unloading_stiffness(delta_max)) * delta_max;
  }

  double
  WaltonBraunLaw::minimum_overlap(const double delta_max) const
  {
    if (delta_max <= 0.0)
      return 0.0;
    const double k2 = unloading_stiffness(delta_max);
    return (k2 - spring.k1) / (k2 + spring.kc) * delta_max;
  }

  ContactResponse
  WaltonBraunLaw::response(const double delta, const double delta_max) const
  {
    if (delta <= 0.0)
      return {};
    ContactResponse r;
    r.contact_radius = std::sqrt(R * delta);
    if (delta >= delta_max)
      {
        r.force     = spring.k1 * delta;
        r.stiffness = spring.k1;
      }
    else
      spring.unloading_branch(
        delta, delta_max, unloading_stiffness(delta_max), r.force, r.stiffness);
    return r;
  }

  ContactResponse
  WaltonBraunLaw::evaluate(const double          gamma,
                           const ContactHistory &history,
                           const ContactContext &) const
  {
    return response(gamma, delta_max(history));
  }

  ContactHistory
  WaltonBraunLaw::updated_history(const double          gamma,
                                  const ContactHistory &history,
                                  const ContactContext &) const
  {
    return with_largest_overlap(history, gamma);
  }

  double
  WaltonBraunLaw::unloading_stiffness(const double          gamma,
                                      const ContactHistory &history,
                                      const ContactContext &) const
  {
    // Loading beyond delta_max: the un/reloading branch that starts here.
    // Already below it: the branch the contact is on (un/reloading,
    // adhesive, or none).
    if (gamma > 0.0 && gamma >= delta_max(history))
      return unloading_stiffness(gamma);
    return response(gamma, delta_max(history)).stiffness;
  }

  bool
  WaltonBraunLaw::loads_plastically(const double          gamma,
                                    const ContactHistory &history,
                                    const ContactContext &) const
  {
    return gamma > std::max(delta_max(history), 0.0);
  }
} // namespace compax::dem
