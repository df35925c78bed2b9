#pragma once

#include "dem/rve/periodic_assembler.h"
#include "dem/rve/periodic_bed.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/steihaug_cg.h"
#include "dem/solver/trust_region_newton.h"

#include <Eigen/Core>

namespace compax::dem
{
  /// 6x6 matrix in Voigt order (xx, yy, zz, yz, xz, xy).
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  using Vector6d = Eigen::Matrix<double, 6, 1>;

  /**
   * Homogenized Cauchy stress of a periodic cell by the Love-Weber formula,
   * sigma = (1/V) sum_c f_c (x) l_c, over the contacts with the force
   * f_c = P n on particle i and the branch vector l_c = -d to the image
   * of j: sigma = -(1/V) sum_c P |d| n n^T [Pa], tension positive.
   */
  Eigen::Matrix3d
  love_weber_stress(const PeriodicBed &bed);

  /// Voigt vector (xx, yy, zz, yz, xz, xy) of a symmetric tensor.
  Vector6d
  to_voigt(const Eigen::Matrix3d &t);

  /// Symmetric strain tensor of a Voigt strain vector with engineering
  /// shears (gamma_yz = 2 eps_yz, ...).
  Eigen::Matrix3d
  strain_from_voigt(const Vector6d &v);

  /// Tangents of an equilibrated cell, dsigma/deps in Voigt notation with
  /// engineering shear strains [Pa].
  struct CellTangents
  {
    /// With the fluctuations relaxed (static condensation of K).
    Matrix6d condensed = Matrix6d::Zero();
    /// With every particle following the macroscopic strain (affine).
    Matrix6d affine = Matrix6d::Zero();
    /// CG iterations of the six condensation solves.
    int cg_iterations = 0;
    /// Whether the sparse direct fallback was used.
    bool direct = false;
  };

  /**
   * Tangent C = dsigma/deps of the Love-Weber stress of an equilibrated
   * cell at fixed internal variables, for a strain increment eps applied
   * to the current configuration (H -> (I + eps) H, x_i -> (I + eps) x_i
   * + w_i), the fluctuations w following by equilibrium:
   *
   *   V dsigma = (A - G^T K^{-1} G) eps - V sigma tr(eps),
   *
   * where for every contact with branch d, force gradient g = -P n and
   * block k = dg/dd, A = sum_c (k d) (x) d + g (x) I (x) d is the affine
   * derivative of sum_c g (x) d, and G eps gives the out-of-balance forces
   * of the affine motion (sum_c +-k eps d on i and j). The six columns of
   * K^{-1} G come from preconditioned CG; K is singular along rigid
   * translations and rattlers, to which G is orthogonal. (At equilibrium
   * the derivative of sum_c g (x) d along w is G^T w exactly: the extra
   * term is sum_i F_i (x) w_i = 0.) The six columns of K^{-1} G come
   * from block-Jacobi preconditioned CG to 1e-6 (a product with K costs
   * O(N), and a jammed K is well enough conditioned; at 1000 particles
   * this was 5x faster than a sparse LDL^T, and the tangent agrees with
   * central differences to ~1e-6). Where CG meets negative
   * curvature (an unstable state) the columns come from a sparse LDL^T of
   * K (Eigen, AMD ordering) shifted by 1e-10 of its mean diagonal, a shift
   * that only removes the null space of rigid translations and rattlers,
   * to which G is orthogonal.
   */
  class TangentCalculator
  {
  public:
    /// How K^{-1} G is found.
    enum class Method
    {
      /// PCG, with the direct fallback on negative curvature.
      iterative,
      /// Always the sparse LDL^T.
      direct
    };

    explicit TangentCalculator(Method method = Method::iterative)
        : method(method)
    {
    }

    CellTangents
    compute(PeriodicBed        &bed,
            const ContactModel &model,
            ContactBranch       branch = ContactBranch::current);

  private:
    /// X = K^{-1} G by CG; false if CG met negative curvature or stalled.
    bool
    solve_iteratively(const Eigen::MatrixXd &G,
                      Eigen::MatrixXd       &X,
                      int                   &iterations);

    /// X = K^{-1} G by a shifted sparse LDL^T.
    void
    solve_directly(const Eigen::MatrixXd &G, Eigen::MatrixXd &X) const;

    Method                    method;
    PeriodicAssembler         assembler;
    BlockSparseMatrix         K;
    BlockJacobiPreconditioner M;
    SteihaugCG                cg;
    Eigen::VectorXd           F, g, s;
  };

  /**
   * The same tangent by central differences: for each Voigt direction the
   * cell is strained by +-h (engineering shears) from its current state,
   * re-equilibrated with frozen histories, and the Love-Weber stresses
   * differenced. The reference for the condensed tangent; it costs twelve
   * equilibrium solves. Throws if an equilibrium does not converge.
   */
  Matrix6d
  finite_difference_tangent(const PeriodicBed        &bed,
                            const ContactModel       &model,
                            double                    strain_step,
                            const EquilibriumOptions &options);
} // namespace compax::dem
