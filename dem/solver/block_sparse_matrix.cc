#include "dem/solver/block_sparse_matrix.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace compax::dem
{
  void
  BlockSparseMatrix::reinit(const std::size_t                n,
                            const std::vector<ParticlePair> &pairs)
  {
    row_start.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
      row_start[i + 1] = 1;
    for (const auto &[i, j] : pairs)
      {
        ++row_start[i + 1];
        ++row_start[j + 1];
      }
    for (std::size_t i = 0; i < n; ++i)
      row_start[i + 1] += row_start[i];
    columns.resize(row_start[n]);
    std::vector<std::uint32_t> next(row_start.begin(), row_start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      columns[next[i]++] = static_cast<std::uint32_t>(i);
    for (const auto &[i, j] : pairs)
      {
        columns[next[i]++] = j;
        columns[next[j]++] = i;
      }
    // Sort and remove duplicates row by row, compacting in place.
    std::size_t out = 0;
    diagonal.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      {
        const auto begin = columns.begin() + row_start[i];
        const auto end   = columns.begin() + row_start[i + 1];
        std::sort(begin, end);
        const auto last  = std::unique(begin, end);
        const auto first = out;
        for (auto it = begin; it != last; ++it)
          {
            if (*it == i)
              diagonal[i] = static_cast<std::uint32_t>(out);
            columns[out++] = *it;
          }
        row_start[i] = static_cast<std::uint32_t>(first);
      }
    row_start[n] = static_cast<std::uint32_t>(out);
    columns.resize(out);
    values.assign(9 * out, 0.0);
  }

  std::size_t
  BlockSparseMatrix::slot(const std::size_t i, const std::size_t j) const
  {
    const auto begin = columns.begin() + row_start[i];
    const auto end   = columns.begin() + row_start[i + 1];
    const auto it    = std::lower_bound(begin, end, j);
    if (it == end || *it != j)
      throw std::out_of_range("block not in the stiffness pattern");
    return it - columns.begin();
  }

  void
  BlockSparseMatrix::set_zero()
  {
    std::fill(values.begin(), values.end(), 0.0);
  }

  void
  BlockSparseMatrix::vmult(Eigen::VectorXd       &dst,
                           const Eigen::VectorXd &src) const
  {
    const auto    n = static_cast<std::ptrdiff_t>(n_block_rows());
    const double *x = src.data();
    double       *y = dst.data();
    // Rows are independent and each sums its blocks in column order, so
    // the product is the same on any number of threads.
#pragma omp parallel for schedule(static) if (n >= parallel_particles)
    for (std::ptrdiff_t i = 0; i < n; ++i)
      {
        double y0 = 0.0, y1 = 0.0, y2 = 0.0;
        for (std::uint32_t k = row_start[i]; k < row_start[i + 1]; ++k)
          {
            const double *a  = values.data() + 9 * k;
            const double *xj = x + 3 * columns[k];
            y0 += a[0] * xj[0] + a[1] * xj[1] + a[2] * xj[2];
            y1 += a[3] * xj[0] + a[4] * xj[1] + a[5] * xj[2];
            y2 += a[6] * xj[0] + a[7] * xj[1] + a[8] * xj[2];
          }
        y[3 * i]     = y0;
        y[3 * i + 1] = y1;
        y[3 * i + 2] = y2;
      }
  }

  Eigen::SparseMatrix<double>
  BlockSparseMatrix::to_sparse() const
  {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(values.size());
    const std::size_t n = n_block_rows();
    for (std::size_t i = 0; i < n; ++i)
      for (std::uint32_t k = row_start[i]; k < row_start[i + 1]; ++k)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            t.emplace_back(3 * i + a,
                           3 * columns[k] + b,
                           values[9 * k + 3 * a + b]);
    Eigen::SparseMatrix<double> m(3 * n, 3 * n);
    m.setFromTriplets(t.begin(), t.end());
    return m;
  }
} // namespace compax::dem
