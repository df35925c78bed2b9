#pragma once

#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_sums.h"

#include <Eigen/Core>

#include <cstddef>

namespace compax::dem
{
  /**
   * A set of spheres whose centres are the unknowns of a static
   * equilibrium, seen by the solvers (TrustRegionNewton, FireRelaxation)
   * only through its stored energy's gradient F and Hessian K. A die bed
   * (punches and die wall) and a periodic RVE cell (images across a
   * deformed lattice) are two such systems; the solvers do not know which.
   *
   * Everything else (walls, cell, contact list, internal variables) is
   * fixed during a solve; the contact list may be refreshed by residual()
   * and assemble() when particles have moved far enough.
   */
  class EquilibriumSystem
  {
  public:
    virtual ~EquilibriumSystem() = default;

    virtual std::size_t
    n_particles() const = 0;

    /// Mean particle radius [m], the length scale of the convergence test.
    virtual double
    mean_radius() const = 0;

    /// Verlet skin of the contact list [m]: no particle may move farther
    /// than a fraction of it in one step.
    virtual double
    skin() const = 0;

    /// All 3N centre coordinates as one writable vector [m].
    virtual Eigen::Map<Eigen::VectorXd>
    coordinates() = 0;

    /// The residual F (out-of-balance internal force, 3N) [N].
    virtual ContactSums
    residual(Eigen::VectorXd &F)
      = 0;

    /// F and its Jacobian K = dF/dx.
    virtual ContactSums
    assemble(Eigen::VectorXd &F, BlockSparseMatrix &K)
      = 0;

    /**
     * Lowers factor[i] (initially 1) so that the step factor[i] s_i of each
     * particle closes no gap to a contact that the quadratic model does
     * not see (virgin and apart) by more than the gap plus `allowance`;
     * returns whether it lowered any.
     */
    virtual bool
    limit_closing(const Eigen::VectorXd &s, Eigen::VectorXd &factor) const = 0;

    /**
     * Matrix-free products, at the state of the last residual() or
     * assemble(), for a system whose assembled K only approximates dF/dx
     * (the nonlocal formulation): the symmetric model Hessian of the
     * trust-region subproblem, and the exact Jacobian J v = dF/dx v of
     * Newton-Krylov. They return false where the assembled K is that
     * operator (every local contact law: K is the Hessian of the stored
     * energy); the solvers then apply K.
     */
    virtual bool
    apply_model_hessian(const Eigen::VectorXd &, Eigen::VectorXd &)
    {
      return false;
    }

    virtual bool
    apply_exact_jacobian(const Eigen::VectorXd &, Eigen::VectorXd &)
    {
      return false;
    }
  };
} // namespace compax::dem
