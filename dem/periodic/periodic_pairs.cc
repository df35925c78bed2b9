#include "dem/periodic/periodic_pairs.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  void
  PeriodicCellGrid::find_pairs(const PeriodicCell                 &cell,
                               const std::vector<Eigen::Vector3d> &positions,
                               const std::vector<double>          &radii,
                               const double                        margin,
                               std::vector<ImagePair>             &pairs)
  {
    pairs.clear();
    const std::size_t n = positions.size();
    if (n == 0)
      return;
    double r_max = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      r_max = std::max(r_max, radii[i]);
    const double reach = 2.0 * r_max + margin;

    // Fractional coordinates, wrapped along periodic directions.
    wrapped.resize(n);
    shift.resize(n);
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300);
    Eigen::Vector3d hi = Eigen::Vector3d::Constant(-1e300);
    for (std::size_t i = 0; i < n; ++i)
      {
        Eigen::Vector3d s = cell.fractional(positions[i]);
        for (int d = 0; d < 3; ++d)
          {
            shift[i][d] = 0;
            if (cell.periodic(d))
              {
                const double k = std::floor(s[d]);
                shift[i][d]    = static_cast<std::int32_t>(k);
                s[d] -= k;
                if (s[d] >= 1.0) // rounding of tiny negative values
                  s[d] = 0.0;
              }
          }
        wrapped[i] = s;
        lo         = lo.cwiseMin(s);
        hi         = hi.cwiseMax(s);
      }

    // Bins: fractional width at least reach / width along each direction.
    int    dims[3];
    double bin_width[3], origin[3];
    for (int d = 0; d < 3; ++d)
      {
        const double w = cell.width(d);
        if (cell.periodic(d))
          {
            if (w < reach)
              throw std::invalid_argument(
                "periodic cell narrower than 2 R_max + margin");
            dims[d]      = std::max(1, static_cast<int>(w / reach));
            bin_width[d] = 1.0 / dims[d];
            origin[d]    = 0.0;
          }
        else
          {
            bin_width[d]      = reach / w;
            origin[d]         = lo[d];
            const double span = hi[d] - lo[d];
            dims[d]
              = std::max(1,
                         std::min(static_cast<int>(span / bin_width[d]) + 1,
                                  static_cast<int>(4 * n + 4)));
            bin_width[d] = std::max(bin_width[d], span / dims[d]);
          }
      }
    const std::size_t n_bins
      = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];

    auto coordinate = [&](const Eigen::Vector3d &s, const int d) {
      return std::clamp(static_cast<int>((s[d] - origin[d]) / bin_width[d]),
                        0,
                        dims[d] - 1);
    };
    bin_of.resize(n);
    bin_start.assign(n_bins + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
      {
        const int c[3] = {coordinate(wrapped[i], 0),
                          coordinate(wrapped[i], 1),
                          coordinate(wrapped[i], 2)};
        bin_of[i]      = (c[2] * dims[1] + c[1]) * dims[0] + c[0];
        ++bin_start[bin_of[i] + 1];
      }
    for (std::size_t b = 0; b < n_bins; ++b)
      bin_start[b + 1] += bin_start[b];
    bin_particles.resize(n);
    bin_cursor.assign(bin_start.begin(), bin_start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      bin_particles[bin_cursor[bin_of[i]]++] = static_cast<std::uint32_t>(i);

    const Eigen::Matrix3d &H = cell.lattice();
    for (std::size_t i = 0; i < n; ++i)
      {
        const Eigen::Vector3d &si = wrapped[i];
        const int              c[3]
          = {coordinate(si, 0), coordinate(si, 1), coordinate(si, 2)};
        for (int oz = -1; oz <= 1; ++oz)
          for (int oy = -1; oy <= 1; ++oy)
            for (int ox = -1; ox <= 1; ++ox)
              {
                const int    o[3] = {ox, oy, oz};
                int          b[3];
                LatticeImage image{0, 0, 0};
                bool         inside = true;
                for (int d = 0; d < 3 && inside; ++d)
                  {
                    b[d] = c[d] + o[d];
                    if (cell.periodic(d))
                      {
                        if (b[d] < 0)
                          {
                            b[d] += dims[d];
                            image[d] = -1;
                          }
                        else if (b[d] >= dims[d])
                          {
                            b[d] -= dims[d];
                            image[d] = 1;
                          }
                      }
                    else if (b[d] < 0 || b[d] >= dims[d])
                      inside = false;
                  }
                if (!inside)
                  continue;
                const std::size_t k = (b[2] * dims[1] + b[1]) * dims[0] + b[0];
                for (std::uint32_t q = bin_start[k]; q < bin_start[k + 1]; ++q)
                  {
                    const std::uint32_t j = bin_particles[q];
                    if (j <= i)
                      continue;
                    Eigen::Vector3d ds = wrapped[j] - si;
                    for (int d = 0; d < 3; ++d)
                      ds[d] += image[d];
                    const double          r   = radii[i] + radii[j] + margin;
                    const Eigen::Vector3d sep = H * ds;
                    if (sep.squaredNorm() < r * r)
                      {
                        LatticeImage m;
                        for (int d = 0; d < 3; ++d)
                          m[d] = image[d] - shift[j][d] + shift[i][d];
                        pairs.push_back({static_cast<std::uint32_t>(i), j, m});
                      }
                  }
              }
      }
    std::sort(pairs.begin(), pairs.end());
  }

  std::vector<ImagePair>
  brute_force_image_pairs(const PeriodicCell                 &cell,
                          const std::vector<Eigen::Vector3d> &positions,
                          const std::vector<double>          &radii,
                          const double                        margin,
                          const int                           max_image)
  {
    std::vector<ImagePair> pairs;
    const int              range[3] = {cell.periodic(0) ? max_image : 0,
                          cell.periodic(1) ? max_image : 0,
                          cell.periodic(2) ? max_image : 0};
    for (std::size_t i = 0; i < positions.size(); ++i)
      for (std::size_t j = i + 1; j < positions.size(); ++j)
        for (int a = -range[0]; a <= range[0]; ++a)
          for (int b = -range[1]; b <= range[1]; ++b)
            for (int c = -range[2]; c <= range[2]; ++c)
              {
                const LatticeImage n{a, b, c};
                const double       r = radii[i] + radii[j] + margin;
                if ((positions[j] - positions[i] + cell.image_offset(n))
                      .squaredNorm()
                    < r * r)
                  pairs.push_back({static_cast<std::uint32_t>(i),
                                   static_cast<std::uint32_t>(j),
                                   n});
              }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
  }
} // namespace compax::dem
