#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace compax::dem
{
  /**
   * Axisymmetric spherical-harmonic spectra of the granular fabric about the
   * compaction axis z (Gonzalez 2018, Eqs. 21-22): the orientation
   * distribution of contact normals
   *   4 pi xi(theta) = 1 + a20 P2 + a40 P4 + a60 P6 + a80 P8
   * and of the mean contact force
   *   f(theta) / f_avg = 1 + b20 P2 + b40 P4 + b60 P6 + b80 P8,
   * with P_l the Legendre polynomials of cos(theta) (the bracketed
   * polynomials of Eqs. 21-22 are exactly P2, P4, P6, P8).
   *
   * Both are least-squares fits of the expansion to histograms over
   * |cos(theta)| in bins of equal solid angle (a contact normal n and -n
   * are the same contact), as the paper fits the distributions.
   */
  struct FabricSpectrum
  {
    /// a20, a40, a60, a80 of the contact-normal distribution.
    std::array<double, 4> a;
    /// b20, b40, b60, b80 of the mean contact force distribution.
    std::array<double, 4> b;
    /// Bin centres of |cos(theta)| and the measured 4 pi xi and f/f_avg.
    std::vector<double> cos_theta, normal_density, force_ratio;
  };

  /**
   * @param normals unit contact normals (either orientation)
   * @param forces contact force magnitudes, same order; only contacts
   *   with non-zero force should be passed
   * @param bins number of |cos(theta)| bins (>= 5)
   */
  FabricSpectrum
  fit_fabric(const std::vector<Eigen::Vector3d> &normals,
             const std::vector<double>          &forces,
             unsigned int                        bins = 20);

  /// Legendre polynomial P_l(x) for l = 0, 2, 4, 6, 8.
  double
  legendre(unsigned int l, double x);
} // namespace compax::dem
