#include "dem/particles/particle_system.h"

#include "dem/numbers.h"

#include <algorithm>

namespace compax::dem
{
  void
  ParticleSystem::add(const Eigen::Vector3d &x,
                      const double           radius,
                      const unsigned int     material)
  {
    positions.push_back(x);
    radii.push_back(radius);
    materials.push_back(material);
  }

  double
  ParticleSystem::solid_volume() const
  {
    double v = 0.0;
    for (const double r : radii)
      v += 4.0 / 3.0 * pi * r * r * r;
    return v;
  }

  double
  ParticleSystem::mean_radius() const
  {
    if (radii.empty())
      return 0.0;
    double s = 0.0;
    for (const double r : radii)
      s += r;
    return s / radii.size();
  }

  double
  ParticleSystem::max_radius() const
  {
    return radii.empty() ? 0.0 : *std::max_element(radii.begin(), radii.end());
  }

  Eigen::Map<Eigen::VectorXd>
  ParticleSystem::coordinates()
  {
    return {positions.empty() ? nullptr : positions[0].data(),
            static_cast<Eigen::Index>(3 * positions.size())};
  }

  Eigen::Map<const Eigen::VectorXd>
  ParticleSystem::coordinates() const
  {
    return {positions.empty() ? nullptr : positions[0].data(),
            static_cast<Eigen::Index>(3 * positions.size())};
  }
} // namespace compax::dem
