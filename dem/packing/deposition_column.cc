#include "dem/packing/deposition_column.h"

#include <algorithm>
#include <cmath>

namespace compax::dem
{
  DepositionColumn::DepositionColumn(const DepositionContainer container,
                                     const double              width,
                                     const double              largest_radius)
      : container(container)
      , width(width)
      , grid(width,
             2.0 * largest_radius,
             container == DepositionContainer::periodic_square)
  {
  }

  Eigen::Vector3d
  DepositionColumn::random_start(RandomSource &random, const double R) const
  {
    Eigen::Vector3d x(0.0, 0.0, R);
    switch (container)
      {
        case DepositionContainer::cylinder:
          {
            // Uniform in the disk of radius D/2 - R, by rejection.
            const double reach = 0.5 * width - R;
            do
              {
                x[0] = random.uniform(-reach, reach);
                x[1] = random.uniform(-reach, reach);
              }
            while (x[0] * x[0] + x[1] * x[1] > reach * reach);
            break;
          }
        case DepositionContainer::periodic_square:
          {
            const double reach = 0.5 * width;
            x[0]               = random.uniform(-reach, reach);
            x[1]               = random.uniform(-reach, reach);
            break;
          }
        case DepositionContainer::square:
          {
            // y is drawn before x: the order of the square die's packings
            // since they were first written.
            const double reach = 0.5 * width - R;
            x[1]               = random.uniform(-reach, reach);
            x[0]               = random.uniform(-reach, reach);
            break;
          }
      }
    return x;
  }

  template <bool periodic>
  Eigen::Vector3d
  DepositionColumn::offset(const Eigen::Vector3d &x,
                           const Eigen::Vector3d &y) const
  {
    Eigen::Vector3d d = x - y;
    if (periodic)
      for (int k = 0; k < 2; ++k)
        d[k] -= width * std::round(d[k] / width);
    return d;
  }

  bool
  DepositionColumn::confine(Eigen::Vector3d &q, const double R) const
  {
    const double reach = 0.5 * width - R;
    switch (container)
      {
        case DepositionContainer::cylinder:
          {
            const double r = std::hypot(q[0], q[1]);
            if (r <= reach)
              return false;
            q[0] *= reach / r;
            q[1] *= reach / r;
            return true;
          }
        case DepositionContainer::periodic_square:
          for (int k = 0; k < 2; ++k)
            q[k] -= width * std::floor(q[k] / width + 0.5);
          return false;
        case DepositionContainer::square:
          {
            bool moved = false;
            for (int k = 0; k < 2; ++k)
              if (std::abs(q[k]) > reach)
                {
                  q[k]  = std::copysign(reach, q[k]);
                  moved = true;
                }
            return moved;
          }
      }
    return false;
  }

  template <bool periodic>
  bool
  DepositionColumn::project(Eigen::Vector3d &q, const double R) const
  {
    for (int sweep = 0; sweep < 200; ++sweep)
      {
        bool moved = false;
        if (q[2] < R)
          {
            q[2]  = R;
            moved = true;
          }
        moved = confine(q, R) || moved;
        grid.for_each_near(q, false, [&](const std::uint32_t j) {
          const Eigen::Vector3d d = offset<periodic>(q, particles.positions[j]);
          const double          s = R + particles.radii[j];
          const double          dist = d.norm();
          if (dist < s * (1.0 - 1e-13))
            {
              // Onto the sphere's surface around its nearest image.
              const Eigen::Vector3d centre
                = periodic ? Eigen::Vector3d(q - d) : particles.positions[j];
              q = centre
                  + (dist > 0.0 ? d / dist : Eigen::Vector3d::UnitZ().eval())
                      * s;
              if (periodic)
                confine(q, R);
              moved = true;
            }
        });
        if (!moved)
          return true;
      }
    return false;
  }

  void
  DepositionColumn::drop(const Eigen::Vector3d &start,
                         const double           R,
                         const unsigned int     material)
  {
    const bool periodic = container == DepositionContainer::periodic_square;
    // Fall: the highest first contact below.
    Eigen::Vector3d x = start;
    x[2]              = R;
    grid.for_each_near(x, true, [&](const std::uint32_t j) {
      const Eigen::Vector3d d  = periodic
                                   ? offset<true>(x, particles.positions[j])
                                   : offset<false>(x, particles.positions[j]);
      const double          s  = R + particles.radii[j];
      const double          h2 = d[0] * d[0] + d[1] * d[1];
      if (h2 < s * s)
        x[2]
          = std::max(x[2], particles.positions[j][2] + std::sqrt(s * s - h2));
    });

    // Roll down by projected descent.
    double h = 0.25 * R;
    for (int it = 0; it < 100000 && h > 1e-6 * R; ++it)
      {
        Eigen::Vector3d q = x;
        q[2] -= h;
        const bool free = periodic ? project<true>(q, R) : project<false>(q, R);
        if (free && q[2] < x[2] - 1e-9 * h)
          {
            x = q;
            h = std::min(0.25 * R, 1.2 * h);
          }
        else
          h *= 0.5;
      }
    particles.add(x, R, material);
    grid.insert(x, static_cast<std::uint32_t>(particles.size() - 1));
  }
} // namespace compax::dem
