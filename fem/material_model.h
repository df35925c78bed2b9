#pragma once

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <filesystem>
#include <string>

namespace compax::fem
{
  /**
   * What the solver hands a material point for one load increment of the
   * updated-Lagrangian scheme (see TabletSolver): the kinematics of the
   * increment measured on the configuration at its start. Always 3-D: the
   * axisymmetric model passes its (r, z, theta) components, the hoop
   * direction included.
   */
  struct MaterialIncrement
  {
    /// Small-strain increment sym(grad du) [-] (hoop du_r/r included).
    dealii::SymmetricTensor<2, 3> strain_increment;
    /// Incremental deformation gradient I + grad du [-], for laws that work
    /// with deformations (an RVE) and for the mass balance.
    dealii::Tensor<2, 3> deformation_increment
      = dealii::unit_symmetric_tensor<3>();
  };

  /// What a material point returns for a trial increment.
  struct MaterialResponse
  {
    /// Cauchy stress at the end of the increment [Pa], tension positive.
    dealii::SymmetricTensor<2, 3> stress;
    /// Consistent tangent d stress / d strain_increment [Pa].
    dealii::SymmetricTensor<4, 3> tangent;
  };

  /**
   * The one interface of every continuum law of the tablet model: linear
   * hypoelasticity, the density-dependent Drucker-Prager Cap and, later,
   * RVE-backed laws. A law owns a fixed number of history values per
   * quadrature point, stored by the caller; evaluate() reads the committed
   * history and writes a trial history, so trial evaluations (Newton
   * iterations, finite differences, step cuts) never mutate the committed
   * state: committing is copying trial over committed, reverting is not
   * copying (QuadratureHistory does both).
   *
   * Every law keeps at least the Cauchy stress and the relative density
   * (solid volume / enclosed volume, mass balance rho_new = rho_old /
   * det(deformation_increment)) and reports them through the accessors.
   */
  class MaterialModel
  {
  public:
    virtual ~MaterialModel() = default;

    /// Short name for logs, e.g. "drucker-prager-cap".
    virtual std::string
    name() const = 0;

    /// History values per quadrature point.
    virtual unsigned int
    n_history() const = 0;

    /// Fills @p history with the unstressed state at relative density
    /// @p relative_density.
    virtual void
    initialize(double                    relative_density,
               dealii::ArrayView<double> history) const = 0;

    /**
     * Stress and consistent tangent after @p increment from the committed
     * state @p old_history; the state that would result is written to
     * @p new_history (same length, distinct storage). Must not throw for
     * any finite increment; a law that cannot return (e.g. a failed local
     * Newton) returns false and the solver cuts the step.
     */
    virtual bool
    evaluate(const MaterialIncrement        &increment,
             dealii::ArrayView<const double> old_history,
             dealii::ArrayView<double>       new_history,
             MaterialResponse               &response) const = 0;

    /// Cauchy stress [Pa] stored in @p history.
    virtual dealii::SymmetricTensor<2, 3>
    stress(dealii::ArrayView<const double> history) const = 0;

    /// Relative density [-] stored in @p history.
    virtual double
    relative_density(dealii::ArrayView<const double> history) const = 0;

    /// Accumulated plastic strain tensor [-] (zero for elastic laws).
    virtual dealii::SymmetricTensor<2, 3>
    plastic_strain(dealii::ArrayView<const double> history) const = 0;

    /// A representative Young's modulus [Pa] of the state (scales the
    /// contact penalty).
    virtual double
    youngs_modulus(dealii::ArrayView<const double> history) const = 0;

    /**
     * Relative accuracy of the stresses this law returns [-]: the solver
     * does not ask for an equilibrium residual below it (times the force
     * scale). Closed-form laws: 0. A law that solves a sub-problem to a
     * tolerance, or whose response switches discontinuously at this level
     * (an RVE's contact events), cannot be balanced more finely.
     */
    virtual double
    stress_resolution() const
    {
      return 0.0;
    }

    /**
     * Rotates the tensorial history by the rotation @p R of a converged
     * increment (objectivity of the hypoelastic update, applied when the
     * increment is committed). Default: rotates stress and plastic strain
     * stored by the helpers below.
     */
    virtual void
    rotate(dealii::ArrayView<double>   history,
           const dealii::Tensor<2, 3> &R) const = 0;

    /**
     * Writes the state a law keeps outside the quadrature histories (e.g.
     * the RVE of every material point of an FE2 law) to @p folder, in files
     * of MPI rank @p rank only; called by the solver's checkpoint beside
     * its own file of that rank. Default: nothing (a law whose whole state
     * is in the histories). Throws std::runtime_error if it cannot write.
     */
    virtual void
    save_state(const std::filesystem::path & /*folder*/,
               unsigned int /*rank*/) const
    {
    }

    /**
     * Restores the state save_state() wrote for MPI rank @p rank, after the
     * solver has initialized its points (the same points, in the same
     * order) and loaded their histories. Default: nothing. Throws
     * std::runtime_error if the files are missing or do not match.
     */
    virtual void
    load_state(const std::filesystem::path & /*folder*/,
               unsigned int /*rank*/) const
    {
    }
  };

  /// Packs the 6 independent components of @p t at @p offset of @p h.
  void
  store(const dealii::SymmetricTensor<2, 3> &t,
        dealii::ArrayView<double>            h,
        unsigned int                         offset);

  /// Unpacks 6 components stored by store().
  dealii::SymmetricTensor<2, 3>
  load(dealii::ArrayView<const double> h, unsigned int offset);

  /// Rotation of the increment: Hughes-Winget R = (I - W/2)^-1 (I + W/2)
  /// with W the skew part of F_inc - I.
  dealii::Tensor<2, 3>
  incremental_rotation(const dealii::Tensor<2, 3> &deformation_increment);

  /// R t R^T.
  dealii::SymmetricTensor<2, 3>
  rotate(const dealii::SymmetricTensor<2, 3> &t, const dealii::Tensor<2, 3> &R);

  /// Pressure p = -tr(sigma)/3 [Pa], positive in compression.
  inline double
  pressure(const dealii::SymmetricTensor<2, 3> &sigma)
  {
    return -dealii::trace(sigma) / 3.0;
  }

  /// Von Mises equivalent stress q = sqrt(3/2 s:s) [Pa].
  double
  von_mises(const dealii::SymmetricTensor<2, 3> &sigma);
} // namespace compax::fem
