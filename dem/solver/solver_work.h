#pragma once

/**
 * @file
 * The work the equilibrium solves of a run did, for performance reports:
 * one record that a solve reports, the load steps add up, the die protocol
 * keeps across a checkpoint and a study reports.
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
    /// Time in assemblies, linear solves and relaxations [s].
    double assembly_seconds = 0.0;
    double linear_seconds   = 0.0;
    double fire_seconds     = 0.0;

    /// Adds the work of another solve, sub-step or load step.
    SolverWork &
    operator+=(const SolverWork &other)
    {
      iterations += other.iterations;
      cg_iterations += other.cg_iterations;
      assemblies += other.assemblies;
      fire_iterations += other.fire_iterations;
      assembly_seconds += other.assembly_seconds;
      linear_seconds += other.linear_seconds;
      fire_seconds += other.fire_seconds;
      return *this;
    }
  };
} // namespace compax::dem
