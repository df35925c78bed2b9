#include "dem/contact/multicontact_adhesive.h"

#include "dem/contact/pair_properties.h"
#include "dem/numbers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace compax::dem
{
  MulticontactAdhesiveLaw::MulticontactAdhesiveLaw(
    const double      effective_radius,
    const double      effective_modulus,
    const Parameters &parameters)
      : R(effective_radius)
      , E(effective_modulus)
      , p(parameters)
      , k1(4.0 / 3.0 * effective_modulus * std::sqrt(effective_radius))
      , k2(parameters.unloading_stiffness_ratio * k1)
      , kc(parameters.adhesion_stiffness_ratio * k1)
      , multicontact_factor(parameters.multicontact_prefactor
                            * parameters.poisson_ratio * pi * effective_radius)
  {
    if (!(parameters.unloading_stiffness_ratio >= 1.0))
      throw std::invalid_argument(
        "multicontact-adhesive: k2/k1 must be at least 1");
    if (!(parameters.adhesion_stiffness_ratio >= 0.0))
      throw std::invalid_argument(
        "multicontact-adhesive: kc/k1 must not be negative");
    if (!(parameters.plasticity_depth >= 0.0))
      throw std::invalid_argument(
        "multicontact-adhesive: phi_f must not be negative");
  }

  MulticontactAdhesiveLaw
  MulticontactAdhesiveLaw::for_pair(const double      R1,
                                    const double      E1,
                                    const double      nu1,
                                    const double      R2,
                                    const double      E2,
                                    const double      nu2,
                                    const Parameters &parameters)
  {
    return MulticontactAdhesiveLaw(dem::effective_radius(R1, R2),
                                   dem::effective_modulus(E1, nu1, E2, nu2),
                                   parameters);
  }

  RegisteredContactLaw
  MulticontactAdhesiveLaw::registration()
  {
    const double         inf = std::numeric_limits<double>::infinity();
    RegisteredContactLaw r;
    r.name        = "multicontact-adhesive";
    r.description = "Giannis 2021, Eqs. 6-14";
    r.subsection  = "Multi-contact";
    r.parameters  = {
       {"Unloading stiffness ratio",
        120.0,
        1.0,
        false,
        1e12,
        false,
        "-",
        "k2/k1 >= 1: largest unloading/reloading stiffness over the loading "
         "stiffness k1 = 4/3 E sqrt(R) (Giannis 2021, Eq. 11; 120 in Table 3)."},
       {"Adhesion stiffness ratio",
        0.5,
        0.0,
        false,
        inf,
        true,
        "-",
        "kc/k1 >= 0: adhesive branch stiffness (Eq. 10)."},
       {"Plasticity depth",
        0.99,
        0.0,
        false,
        inf,
        true,
        "-",
        "phi_f: dimensionless plasticity depth of Eq. (12)."},
       {"Prefactor",
        0.0,
        0.0,
        false,
        inf,
        true,
        "-",
        "beta: multi-contact prefactor of Eq. (13) (0: the conventional, "
         "local model)."},
       {"Pull-off force",
        0.0,
        -inf,
        true,
        inf,
        true,
        "N",
        "F_0: constant pull-off force of Eq. (6)."},
       {"Mean compressive stress",
        0.0,
        -inf,
        true,
        inf,
        true,
        "Pa",
        "-(tr sigma_i + tr sigma_j)/3 of the two particles, positive in "
         "compression: the P_ij of Eq. (13), held constant along the history."}};
    r.make = [](const LawParameterValues &v, const ContactBodies &b) {
      Parameters p;
      p.unloading_stiffness_ratio = v.at("Unloading stiffness ratio");
      p.adhesion_stiffness_ratio  = v.at("Adhesion stiffness ratio");
      p.plasticity_depth          = v.at("Plasticity depth");
      p.multicontact_prefactor    = v.at("Prefactor");
      p.pull_off_force            = v.at("Pull-off force");
      p.poisson_ratio             = b.nu1;
      return std::make_unique<MulticontactAdhesiveLaw>(
        for_pair(b.R1, b.E1, b.nu1, b.R2, b.E2, b.nu2, p));
    };
    // In a packing the particle solver supplies P_ij; for one pair it is
    // a constant of the parameters.
    r.context = [](const LawParameterValues &v, const ContactBodies &) {
      const double compressive_stress = v.at("Mean compressive stress");
      return ContactContextAt([compressive_stress](double) {
        ContactContext context;
        context.particle_pressure = -compressive_stress;
        return context;
      });
    };
    return r;
  }

  double
  MulticontactAdhesiveLaw::plastic_flow_limit() const
  {
    return spring().plastic_flow_limit(p.plasticity_depth, R);
  }

  double
  MulticontactAdhesiveLaw::unloading_stiffness(const double delta_max) const
  {
    return spring().unloading_stiffness(delta_max, plastic_flow_limit());
  }

  double
  MulticontactAdhesiveLaw::plastic_overlap(const double delta_max) const
  {
    if (delta_max <= 0.0)
      return 0.0;
    const double k2s = unloading_stiffness(delta_max);
    return std::cbrt(std::pow(1.0 - k1 / k2s, 2.0)) * delta_max;
  }

  double
  MulticontactAdhesiveLaw::minimum_overlap(const double delta_max) const
  {
    if (delta_max <= 0.0)
      return 0.0;
    const double k2s = unloading_stiffness(delta_max);
    const double q   = (k2s - k1) / (k2s + kc);
    return std::cbrt(q * q) * delta_max;
  }

  double
  MulticontactAdhesiveLaw::minimum_force(const double delta_max) const
  {
    const double d = minimum_overlap(delta_max);
    return -kc * d * std::sqrt(d);
  }

  ContactResponse
  MulticontactAdhesiveLaw::response(const double delta,
                                    const double delta_max,
                                    const double particle_pressure) const
  {
    if (delta <= 0.0)
      return {};
    const double root = std::sqrt(delta);
    const double x    = delta * root;
    const double dx   = 1.5 * root;

    ContactResponse r;
    if (delta >= delta_max)
      {
        r.force     = k1 * x;
        r.stiffness = k1 * dx;
      }
    else
      {
        const double x_max = delta_max * std::sqrt(delta_max);
        double       slope = 0.0;
        spring().unloading_branch(
          x, x_max, unloading_stiffness(delta_max), r.force, slope);
        r.stiffness = slope * dx;
      }
    const double pressure = -particle_pressure;
    r.force += p.pull_off_force + multicontact_factor * delta * pressure;
    r.stiffness += multicontact_factor * pressure;
    r.contact_radius = std::sqrt(R * delta);
    return r;
  }

  ContactResponse
  MulticontactAdhesiveLaw::evaluate(const double          gamma,
                                    const ContactHistory &history,
                                    const ContactContext &context) const
  {
    return response(gamma, delta_max(history), context.particle_pressure);
  }

  ContactHistory
  MulticontactAdhesiveLaw::updated_history(const double          gamma,
                                           const ContactHistory &history,
                                           const ContactContext &) const
  {
    return with_largest_overlap(history, gamma);
  }
} // namespace compax::dem
