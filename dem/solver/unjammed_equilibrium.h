#pragma once

#include <string>

namespace compax::dem
{
  /**
   * What counts as the converged state of a load step while the bed (or
   * cell) is unjammed, on the bonded path. Below jamming the trust-region
   * Newton has no stiffness along the bed's mechanisms, so the variants
   * but the last start with a relaxation at fixed internal variables; they
   * differ in when the relaxation may stop, which decides whether force
   * chains that a balanced loose bed does not carry reach Eq. (13).
   */
  enum class UnjammedEquilibrium
  {
    /// The relaxation, converged at the relaxation tolerance (1e-2 of the
    /// mean contact force) or once every net force is below the study's
    /// force resolution. Fast; accepts chains whose own imbalance is
    /// below the resolution.
    relaxation,
    /// The relaxation, continued by the trust-region Newton to the
    /// equilibrium tolerances (relative force tolerance, or the absolute
    /// force floor).
    relaxation_then_newton,
    /// The relaxation itself run to the equilibrium tolerances (relative
    /// force tolerance, or the absolute force floor), for as long as it
    /// approaches them (LoadSteppingOptions::balanced_stall_window). Near
    /// the jamming onset the bed sits on saddles whose negative curvature
    /// lives on the scale of the overlaps, where Newton's quadratic model
    /// fails for steps a rearrangement needs; FIRE's inertia does not.
    balanced_relaxation,
    /// As balanced_relaxation, with the relaxation done by L-BFGS
    /// (LbfgsRelaxation) instead of FIRE: the same fixed-history problem
    /// and the same tolerances, another minimiser.
    balanced_lbfgs,
    /// No relaxation: Gonzalez 2018 Algorithm 1 as printed
    /// (LeastSquaresTrustRegion), a Gauss-Newton trust region on |F|^2
    /// that stops when its step is shorter than the step tolerance. A
    /// loose bed's net forces along its mechanisms are out of that model's
    /// reach, so its converged states may keep force chains that the
    /// energy minimisers relax.
    least_squares
  };

  /// Whether the loose steps' relaxation runs to the equilibrium
  /// tolerances (balanced_relaxation, balanced_lbfgs).
  bool
  relaxes_to_balance(UnjammedEquilibrium e);

  /// Whether the loose steps' relaxation is L-BFGS rather than FIRE.
  bool
  relaxes_by_lbfgs(UnjammedEquilibrium e);

  /// "relaxation", "relaxation+newton", "balanced-relaxation",
  /// "balanced-lbfgs" or "least-squares".
  std::string
  unjammed_equilibrium_name(UnjammedEquilibrium e);

  /// The inverse of unjammed_equilibrium_name(); throws
  /// std::invalid_argument naming the value for any other text.
  UnjammedEquilibrium
  parse_unjammed_equilibrium(const std::string &name);
} // namespace compax::dem
