#pragma once

#include "dem/solver/relaxation.h"

#include <Eigen/Core>

#include <vector>

namespace compax::dem
{
  /**
   * Limited-memory BFGS minimisation (Nocedal 1980; Nocedal & Wright 2006,
   * Alg. 7.4) of a bed's stored energy at fixed walls and internal
   * variables: the same problem FireRelaxation solves, by a different
   * minimiser. With the histories fixed each contact force is a function
   * of its own overlap, so the residual F is the gradient of an energy
   * and the converged states of both minimisers balance the same forces to
   * the same tolerance.
   *
   * Why a second minimiser: near the jamming onset the slowest mode of a
   * loose bed softens, and FIRE, whose convergence rate is set by the
   * ratio of the stiffest to the softest mode, needs up to 1e5
   * iterations per load step. L-BFGS builds a curvature model of the
   * soft subspace from the last few steps and moves along it in a few
   * line searches.
   *
   * Only forces are available (no energy), so the line search brackets a
   * zero of the directional derivative g(x + a d).d and accepts a step that
   * satisfies the strong Wolfe curvature condition |g(a).d| <= 0.9
   * |g(0).d| with g(a).d <= 0 or after a bracketing secant (Illinois)
   * refinement. The initial inverse Hessian is the block-diagonal
   * preconditioner FIRE uses as its inverse masses (each particle's
   * largest diagonal stiffness), scaled by s.y / y.M^-1 y. No particle
   * moves more than the Verlet skin per trial point. Buffers are kept,
   * so repeated relaxations allocate nothing.
   */
  class LbfgsRelaxation final : public Relaxation
  {
  public:
    using Relaxation::relax;

    /// @param memory Number of correction pairs kept (m in Nocedal & Wright).
    explicit LbfgsRelaxation(int memory = 10);

    /**
     * Minimises until max_i |F_i| <= target_relative_residual times the
     * mean contact force, or max_i |F_i| <= force_floor [N], or until
     * max_evaluations residual evaluations (FireResult::iterations counts
     * residual evaluations, the cost unit FIRE's budget counts too).
     */
    FireResult
    relax(EquilibriumSystem &system,
          double             target_relative_residual,
          int                max_evaluations,
          double             force_floor = 0.0) override;

  private:
    /// d = -H g by the two-loop recursion over the stored pairs; returns
    /// the slope g.d. On a large bed every thread shares its passes, and
    /// its dot products are summed over fixed blocks in block order, so d
    /// is the same on any number of threads.
    double
    search_direction();

    /// The recursion with Eigen's whole-vector dot products, for small
    /// beds.
    double
    plain_search_direction();

    /// Stores the pair (s, y) if its curvature s.y is positive, by
    /// swapping it into the history: s and y then hold an old pair's
    /// buffers, which the next iteration overwrites.
    void
    remember(Eigen::VectorXd &s, Eigen::VectorXd &y);

    int                          memory;
    std::vector<Eigen::VectorXd> s_history, y_history;
    std::vector<double>          rho, alpha;
    /// Each thread's alphas of the two-loop recursion (memory per thread).
    std::vector<double> thread_alpha;
    /// The blocks' terms of a dot product, two buffers used in turn.
    std::vector<double> block_partials[2];
    int                 n_stored = 0, newest = -1;
    double              scaling = 1.0;

    Eigen::VectorXd g, g_trial, d, x0, s, y, inverse_diagonal;
  };
} // namespace compax::dem
