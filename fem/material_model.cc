#include "fem/material_model.h"

#include <cmath>

namespace compax::fem
{
  namespace
  {
    constexpr unsigned int index[6][2]
      = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  }

  void
  store(const dealii::SymmetricTensor<2, 3> &t,
        dealii::ArrayView<double>            h,
        const unsigned int                   offset)
  {
    for (unsigned int k = 0; k < 6; ++k)
      h[offset + k] = t[index[k][0]][index[k][1]];
  }

  dealii::SymmetricTensor<2, 3>
  load(dealii::ArrayView<const double> h, const unsigned int offset)
  {
    dealii::SymmetricTensor<2, 3> t;
    for (unsigned int k = 0; k < 6; ++k)
      t[index[k][0]][index[k][1]] = h[offset + k];
    return t;
  }

  dealii::Tensor<2, 3>
  incremental_rotation(const dealii::Tensor<2, 3> &F)
  {
    const dealii::Tensor<2, 3> I = dealii::unit_symmetric_tensor<3>();
    const dealii::Tensor<2, 3> L = F - I;
    const dealii::Tensor<2, 3> W = 0.5 * (L - dealii::transpose(L));
    return dealii::invert(I - 0.5 * W) * (I + 0.5 * W);
  }

  dealii::SymmetricTensor<2, 3>
  rotate(const dealii::SymmetricTensor<2, 3> &t, const dealii::Tensor<2, 3> &R)
  {
    const dealii::Tensor<2, 3> full
      = R * dealii::Tensor<2, 3>(t) * dealii::transpose(R);
    return dealii::symmetrize(full);
  }

  double
  von_mises(const dealii::SymmetricTensor<2, 3> &sigma)
  {
    const dealii::SymmetricTensor<2, 3> s = dealii::deviator(sigma);
    return std::sqrt(1.5 * (s * s));
  }
} // namespace compax::fem
