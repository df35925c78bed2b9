#pragma once

#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace compax::fem
{
  /**
   * Axisymmetric (torsion-free) kinematics on the r-z half plane, where the
   * mesh coordinates are (x0, x1) = (r, z) and the displacement components
   * are (u_r, u_z).
   *
   * The small strain is returned as a 3-D symmetric tensor in the
   * cylindrical basis ordered (r, z, theta), so that indices 0 and 1 match
   * the mesh coordinates and 2 is the hoop direction:
   *   eps_rr = d u_r/dr,  eps_zz = d u_z/dz,  eps_tt = u_r / r,
   *   eps_rz = (d u_r/dz + d u_z/dr) / 2,  eps_rt = eps_zt = 0.
   * Any 3-D constitutive law sigma(eps) then applies unchanged.
   */

  /// The weight 2 pi r that turns an r-z area integral into a volume one.
  inline double
  axisymmetric_measure(const dealii::Point<2> &p)
  {
    return 2.0 * dealii::numbers::PI * p[0];
  }

  /**
   * Strain of the displacement with value @p u and gradient @p grad_u
   * (grad_u[i][j] = d u_i / d x_j) at radius @p r > 0 (quadrature points
   * never lie on the axis).
   */
  inline dealii::SymmetricTensor<2, 3>
  axisymmetric_strain(const dealii::Tensor<2, 2> &grad_u,
                      const dealii::Tensor<1, 2> &u,
                      const double                r)
  {
    dealii::SymmetricTensor<2, 3> eps;
    eps[0][0] = grad_u[0][0];
    eps[1][1] = grad_u[1][1];
    eps[0][1] = 0.5 * (grad_u[0][1] + grad_u[1][0]);
    eps[2][2] = u[0] / r;
    return eps;
  }
} // namespace compax::fem
