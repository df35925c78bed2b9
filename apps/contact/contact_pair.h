#pragma once

#include "coupling/parameters/material_parameters.h"
#include "dem/contact/contact_law.h"

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace compax::cli
{
  /**
   * One contact pair as `compax contact` sets it up from a .prm: the law
   * built for the two bodies, the context the law needs at each overlap
   * (nonlocal overlap, particle pressure), and the law's closed forms to
   * print beside the sampled results.
   */
  struct ContactPair
  {
    std::unique_ptr<dem::ContactLaw> law;
    /// "sphere-sphere" or "sphere-wall".
    std::string geometry;
    /// Context of the law at overlap gamma (empty context for local laws).
    std::function<dem::ContactContext(double gamma)> context
      = [](double) { return dem::ContactContext{}; };
    /// Closed-form values for a history whose largest overlap is
    /// gamma_max, one printable line each.
    std::function<std::vector<std::string>(double gamma_max)> closed_forms
      = [](double) { return std::vector<std::string>{}; };
  };

  /// Declares Law, Geometry and the subsections Particle 1, Particle 2 and
  /// Bonding (and the law-specific ones).
  void
  declare_contact_pair(dealii::ParameterHandler         &prm,
                       const coupling::ParticleDefaults &defaults);

  /// Builds the pair; throws InputError for inconsistent entries.
  ContactPair
  make_contact_pair(dealii::ParameterHandler &prm);
} // namespace compax::cli
