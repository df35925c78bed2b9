#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace compax::fem
{
  /// Drucker-Prager Cap parameters at one relative density.
  struct DpcParameters
  {
    double cohesion;           ///< d [Pa]
    double tan_friction_angle; ///< tan(beta) [-]
    double cap_eccentricity;   ///< R [-]
    double youngs_modulus;     ///< E [Pa]
    double poisson_ratio;      ///< nu [-]
  };

  /**
   * The density-dependent Drucker-Prager Cap data of a powder, as
   * pharmaceutical FE studies calibrate them (Han et al. 2008, Sinka et
   * al. 2003): cohesion d, friction angle beta, cap eccentricity R, the
   * hydrostatic yield pressure p_b of the cap and the elastic moduli E, nu,
   * each tabulated against relative density. Values between rows are
   * interpolated linearly, except p_b, which grows by orders of magnitude
   * and is interpolated linearly in log(p_b); outside the table the end
   * rows hold (p_b extrapolates log-linearly).
   */
  class DpcTable
  {
  public:
    /// Columns of the CSV file, in this order, with a header line.
    static const std::vector<std::string> &
    columns();

    /// Reads a CSV file with (at least) the columns(), in any order;
    /// friction angle in degrees, stresses and moduli in Pa. Throws
    /// std::runtime_error naming the file, and the line and column of a
    /// malformed cell, on bad input.
    static DpcTable
    read_csv(const std::filesystem::path &file);

    /// Built-in illustrative table for a microcrystalline-cellulose-like
    /// powder: magnitudes of the kind DPC calibrations of MCC report, not a
    /// fit to any data set; use read_csv() for a calibrated material.
    static DpcTable
    microcrystalline_cellulose();

    /// Appends a row; rows must come in increasing relative density.
    void
    add_row(double relative_density,
            double cohesion,
            double friction_angle_degrees,
            double cap_eccentricity,
            double cap_pressure,
            double youngs_modulus,
            double poisson_ratio);

    /// Throws std::invalid_argument unless >= 2 rows, increasing density
    /// and physical values.
    void
    validate() const;

    DpcParameters
    parameters(double relative_density) const;

    /// Hydrostatic yield pressure p_b [Pa] and d p_b / d rho [Pa].
    void
    cap_pressure(double relative_density, double &pb, double &dpb) const;

    std::size_t
    size() const
    {
      return rho.size();
    }

  private:
    std::vector<double> rho, d, tan_beta, R, log_pb, E, nu;
  };
} // namespace compax::fem
