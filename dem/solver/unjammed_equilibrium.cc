#include "dem/solver/unjammed_equilibrium.h"

#include <stdexcept>

namespace compax::dem
{
  bool
  relaxes_to_balance(const UnjammedEquilibrium e)
  {
    return e == UnjammedEquilibrium::balanced_relaxation
           || e == UnjammedEquilibrium::balanced_lbfgs;
  }

  bool
  relaxes_by_lbfgs(const UnjammedEquilibrium e)
  {
    return e == UnjammedEquilibrium::balanced_lbfgs;
  }

  std::string
  unjammed_equilibrium_name(const UnjammedEquilibrium e)
  {
    switch (e)
      {
        case UnjammedEquilibrium::relaxation:
          return "relaxation";
        case UnjammedEquilibrium::relaxation_then_newton:
          return "relaxation+newton";
        case UnjammedEquilibrium::balanced_relaxation:
          return "balanced-relaxation";
        case UnjammedEquilibrium::balanced_lbfgs:
          return "balanced-lbfgs";
        case UnjammedEquilibrium::least_squares:
          return "least-squares";
      }
    return "relaxation";
  }

  UnjammedEquilibrium
  parse_unjammed_equilibrium(const std::string &name)
  {
    for (const auto e : {UnjammedEquilibrium::relaxation,
                         UnjammedEquilibrium::relaxation_then_newton,
                         UnjammedEquilibrium::balanced_relaxation,
                         UnjammedEquilibrium::balanced_lbfgs,
                         UnjammedEquilibrium::least_squares})
      if (unjammed_equilibrium_name(e) == name)
        return e;
    throw std::invalid_argument(
      "unjammed equilibrium '" + name
      + "' is not one of relaxation, relaxation+newton, balanced-relaxation, "
        "balanced-lbfgs, least-squares");
  }
} // namespace compax::dem
