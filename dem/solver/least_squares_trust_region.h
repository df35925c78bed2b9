#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/equilibrium_system.h"
#include "dem/solver/relaxation.h"
#include "dem/solver/steihaug_cg.h"
#include "dem/solver/trust_radius.h"
#include "dem/solver/trust_region_newton.h"

#include <Eigen/Core>

namespace compax::dem
{
  /**
   * Gonzalez 2018, Algorithm 1 as printed: a trust-region method on the
   * nonlinear least-squares problem min |F(x)|^2 / 2 at fixed walls and
   * internal variables. Each step minimises the Gauss-Newton model
   * <K s, F> + <K s, K s> / 2 subject to |s| <= Delta (line 7; Steihaug
   * conjugate gradients on K^2 with the block-Jacobi preconditioner of K),
   * and the iteration stops when Error = |s| < TOL1 (line 10): when an
   * accepted step moves no particle farther than
   * EquilibriumOptions::step_tolerance times the mean radius. It also
   * stops once the bed is balanced to EquilibriumOptions' force tolerance
   * or floor.
   *
   * Where the bed is jammed (K non-singular on the loaded particles) this
   * is Newton's equilibrium. Where it is loose, steps that open or close
   * contacts the model does not see are rejected, the trust radius stays
   * at the scale of the overlaps, and every step lies on its boundary; the
   * Error then falls below TOL1 when a rejection has cut the radius below
   * it, on a state that need not be balanced (doc/loose_regime.md, What ends a
   * loose solve of Algorithm 1). Such a state is converged in Algorithm 1's
   * sense, and Eq. (13) applies to it (LoadStepper with
   * UnjammedEquilibrium::least_squares): the printed protocol's loose
   * states, beside the balanced ones of the energy minimisers.
   * EquilibriumResult::relative_residual reports the imbalance left.
   */
  class LeastSquaresTrustRegion
  {
  public:
    explicit LeastSquaresTrustRegion(EquilibriumOptions options = {});

    /// Solves the die bed at its walls; histories fixed.
    EquilibriumResult
    solve(Bed &bed, const ContactModel &model);

    /// Solves any system.
    EquilibriumResult
    solve(EquilibriumSystem &system);

  private:
    /// The Gauss-Newton model Hessian K^2 / c, with c the preconditioner's
    /// scale, so that it has K's units and conditioning scale.
    struct NormalOperator
    {
      const BlockSparseMatrix &K;
      Eigen::VectorXd         &work;
      double                   scale;

      void
      vmult(Eigen::VectorXd &dst, const Eigen::VectorXd &src) const;
    };

    EquilibriumOptions        opts;
    ContactAssembler          assembler;
    BlockSparseMatrix         K;
    BlockJacobiPreconditioner M;
    SteihaugCG                cg;
    TrustRadius               radius;
    Eigen::VectorXd           F, F_old, x_old, g, s, work;
  };

  /// A least-squares solve reported as the loose step's relaxation
  /// (converged, iterations, residual, sums, assemblies).
  FireResult
  as_relaxation(const EquilibriumResult &r);
} // namespace compax::dem
