#pragma once

#include <cstdint>
#include <random>

namespace compax::dem
{
  /**
   * Seeded random numbers whose sequence is the same with every standard
   * library: std::mt19937_64 is specified bit for bit by the standard, but
   * std::uniform_real_distribution and std::normal_distribution are not, so
   * the distributions are written out here.
   */
  class RandomSource
  {
  public:
    explicit RandomSource(std::uint64_t seed)
        : engine(seed)
    {
    }

    /// Uniform on [0, 1) with 53 random bits.
    double
    uniform()
    {
      return static_cast<double>(engine() >> 11) * 0x1.0p-53;
    }

    /// Uniform on [a, b).
    double
    uniform(double a, double b)
    {
      return a + (b - a) * uniform();
    }

    /// Standard normal by the Box-Muller transform (one value per call).
    double
    normal();

  private:
    std::mt19937_64 engine;
  };

  /**
   * Particle radii: monodisperse, or log-normal (ln R normal with median
   * R_50 and standard deviation sigma of ln R) truncated to
   * [R_min, R_max] by rejection.
   */
  struct SizeDistribution
  {
    /// Monodisperse radius, or median radius of the log-normal [m].
    double median_radius = 220e-6;
    /// Standard deviation of ln R [-]; 0 for monodisperse.
    double log_sigma = 0.0;
    /// Cut-offs [m] (ignored when monodisperse; 0 and inf mean none).
    double min_radius = 0.0;
    double max_radius = 1e300;

    double
    sample(RandomSource &random) const;

    /// Largest radius sample() can return [m].
    double
    largest() const;
  };
} // namespace compax::dem
