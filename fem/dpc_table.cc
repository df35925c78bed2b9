#include "fem/dpc_table.h"

#include "io/csv_table.h"

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace compax::fem
{
  namespace
  {
    /// Index i such that rho[i] <= x < rho[i+1], clamped to the table, and
    /// the weight of rho[i+1].
    std::pair<std::size_t, double>
    bracket(const std::vector<double> &rho, const double x)
    {
      const auto  it = std::upper_bound(rho.begin(), rho.end(), x);
      std::size_t i  = (it == rho.begin()) ? 0 : (it - rho.begin()) - 1;
      i              = std::min(i, rho.size() - 2);
      const double w = (x - rho[i]) / (rho[i + 1] - rho[i]);
      return {i, w};
    }

    double
    lerp(const std::vector<double> &v, std::size_t i, double w)
    {
      w = std::clamp(w, 0.0, 1.0);
      return (1.0 - w) * v[i] + w * v[i + 1];
    }
  } // namespace

  const std::vector<std::string> &
  DpcTable::columns()
  {
    static const std::vector<std::string> names = {"relative_density",
                                                   "cohesion",
                                                   "friction_angle_deg",
                                                   "cap_eccentricity",
                                                   "cap_pressure",
                                                   "youngs_modulus",
                                                   "poisson_ratio"};
    return names;
  }

  void
  DpcTable::add_row(const double relative_density,
                    const double cohesion,
                    const double friction_angle_degrees,
                    const double cap_eccentricity,
                    const double cap_pressure,
                    const double youngs_modulus,
                    const double poisson_ratio)
  {
    rho.push_back(relative_density);
    d.push_back(cohesion);
    tan_beta.push_back(
      std::tan(friction_angle_degrees * dealii::numbers::PI / 180.0));
    R.push_back(cap_eccentricity);
    log_pb.push_back(std::log(std::max(cap_pressure, 1e-300)));
    E.push_back(youngs_modulus);
    nu.push_back(poisson_ratio);
    if (!(cap_pressure > 0.0))
      log_pb.back() = -1.0; // caught by validate()
  }

  void
  DpcTable::validate() const
  {
    if (rho.size() < 2)
      throw std::invalid_argument("DPC table: needs at least two rows");
    for (std::size_t i = 0; i < rho.size(); ++i)
      {
        const std::string row = " (row " + std::to_string(i + 1) + ")";
        if (i > 0 && !(rho[i] > rho[i - 1]))
          throw std::invalid_argument(
            "DPC table: relative density must increase" + row);
        if (!(rho[i] > 0.0 && rho[i] <= 1.0))
          throw std::invalid_argument(
            "DPC table: relative density must lie in (0, 1]" + row);
        if (!(d[i] >= 0.0) || !(tan_beta[i] > 0.0) || !(R[i] > 0.0)
            || !(E[i] > 0.0) || !(nu[i] > -1.0 && nu[i] < 0.5)
            || !(std::exp(log_pb[i]) > 0.0))
          {
            // Name the values: a NaN E or nu is an RVE branch that was not
            // jammed (a loose cell has no elastic moduli).
            std::ostringstream values;
            values << " (row " << i + 1 << ": relative density " << rho[i]
                   << ", cohesion " << d[i] << " Pa, tan beta " << tan_beta[i]
                   << ", R " << R[i] << ", E " << E[i] << " Pa, nu " << nu[i]
                   << ", p_b " << std::exp(log_pb[i])
                   << " Pa; NaN moduli come from an unjammed RVE branch)";
            throw std::invalid_argument(
              "DPC table: need cohesion >= 0, friction angle in (0, 90) deg, "
              "cap eccentricity > 0, cap pressure > 0, E > 0, nu in (-1, 0.5)"
              + values.str());
          }
      }
  }

  DpcTable
  DpcTable::read_csv(const std::filesystem::path &file)
  {
    DpcTable table;
    try
      {
        // By column name: any order, further columns ignored.
        const io::CsvTable               csv = io::CsvTable::read(file);
        std::vector<std::vector<double>> v;
        for (const auto &name : columns())
          v.push_back(csv.numbers(name));
        for (std::size_t r = 0; r < csv.rows(); ++r)
          table.add_row(
            v[0][r], v[1][r], v[2][r], v[3][r], v[4][r], v[5][r], v[6][r]);
        table.validate();
      }
    catch (const io::CsvError &e)
      {
        throw std::runtime_error("DPC table '" + file.string()
                                 + "': " + e.reason());
      }
    catch (const std::invalid_argument &e)
      {
        throw std::runtime_error("DPC table '" + file.string()
                                 + "': " + e.what());
      }
    return table;
  }

  DpcTable
  DpcTable::microcrystalline_cellulose()
  {
    DpcTable t;
    // rho, d [Pa], beta [deg], R, p_b [Pa], E [Pa], nu
    t.add_row(0.30, 0.01e6, 45, 0.30, 0.02e6, 0.01e9, 0.10);
    t.add_row(0.40, 0.05e6, 55, 0.35, 0.15e6, 0.05e9, 0.12);
    t.add_row(0.50, 0.20e6, 60, 0.40, 0.80e6, 0.20e9, 0.14);
    t.add_row(0.60, 0.70e6, 63, 0.45, 4.0e6, 0.8e9, 0.16);
    t.add_row(0.70, 1.80e6, 65, 0.50, 14.0e6, 2.0e9, 0.19);
    t.add_row(0.80, 4.00e6, 67, 0.60, 42.0e6, 4.0e9, 0.23);
    t.add_row(0.90, 8.00e6, 68, 0.70, 120.0e6, 7.0e9, 0.28);
    t.add_row(0.95, 11.0e6, 69, 0.75, 220.0e6, 8.5e9, 0.30);
    t.add_row(1.00, 15.0e6, 70, 0.80, 500.0e6, 10.0e9, 0.32);
    t.validate();
    return t;
  }

  DpcParameters
  DpcTable::parameters(const double x) const
  {
    const auto [i, w] = bracket(rho, x);
    return {lerp(d, i, w),
            lerp(tan_beta, i, w),
            lerp(R, i, w),
            lerp(E, i, w),
            lerp(nu, i, w)};
  }

  void
  DpcTable::cap_pressure(const double x, double &pb, double &dpb) const
  {
    const auto [i, w]  = bracket(rho, x);
    const double slope = (log_pb[i + 1] - log_pb[i]) / (rho[i + 1] - rho[i]);
    pb                 = std::exp((1.0 - w) * log_pb[i] + w * log_pb[i + 1]);
    dpb                = pb * slope;
  }
} // namespace compax::fem
