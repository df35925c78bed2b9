#include "dem/solver/stiffness_scaling.h"

#include <algorithm>

namespace compax::dem
{
  void
  inverse_diagonal_stiffness(const BlockSparseMatrix &K,
                             const std::size_t        n,
                             Eigen::VectorXd         &inverse)
  {
    inverse.resize(3 * n);
    double mean = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      {
        const double *b = K.block(K.diagonal_slot(i));
        mean += std::max({b[0], b[4], b[8], 0.0});
      }
    mean = n > 0 ? mean / n : 0.0;
    if (!(mean > 0.0))
      mean = 1.0;
    for (std::size_t i = 0; i < n; ++i)
      {
        const double *b = K.block(K.diagonal_slot(i));
        const double  k = std::max({b[0], b[4], b[8], 0.05 * mean});
        inverse.segment<3>(3 * i).setConstant(1.0 / k);
      }
  }
} // namespace compax::dem
