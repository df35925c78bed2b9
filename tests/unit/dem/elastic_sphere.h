#pragma once

// The elastic constants of one body of a contact pair, for the tests that
// write the pair laws' constants out by hand (Hertz, nonlocal Hertz,
// multi-contact adhesive).

#include "dem/contact/pair_properties.h"

namespace compax::dem::contact_test
{
  /// Radius R [m], Young's modulus E [Pa] and Poisson's ratio nu [-] of a
  /// sphere.
  struct ElasticSphere
  {
    double R, E, nu;
  };

  /// A rigid flat: infinite radius and modulus, so that it drops out of the
  /// mixing rules.
  inline const ElasticSphere rigid_flat{rigid, rigid, 0.0};
} // namespace compax::dem::contact_test
