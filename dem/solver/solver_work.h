#pragma once

/**
 * @file
 * The work the equilibrium solves of a run did, for performance reports:
 * one record that the load steps add up, the die protocol keeps across a
 * checkpoint and a study reports.
 */

namespace compax::dem
{
  /// Iterations and times of equilibrium solves, summed.
  struct SolverWork
  {
    /// Newton (trust-region) iterations and their conjugate-gradient
    /// iterations [-].
    long iterations    = 0;
    long cg_iterations = 0;
    /// Assemblies of F and K [-].
    long assemblies = 0;
    /// Relaxation iterations (FIRE or L-BFGS) [-].
    long fire_iterations = 0;
    /// Time in assemblies, linear solves and relaxations [s]. The elastic
    /// steppers do not time their work: 0 there.
    double assembly_seconds = 0.0;
    double linear_seconds   = 0.0;
    double fire_seconds     = 0.0;

    /// Adds the work of one solve or load step (EquilibriumResult,
    /// LoadStepResult: both name their work as this record does).
    template <typename Result>
    void
    add(const Result &r)
    {
      iterations += r.iterations;
      cg_iterations += r.cg_iterations;
      assemblies += r.assemblies;
      fire_iterations += r.fire_iterations;
      assembly_seconds += r.assembly_seconds;
      linear_seconds += r.linear_seconds;
      fire_seconds += r.fire_seconds;
    }
  };
} // namespace compax::dem
