#include "dem/analysis/curve_fits.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    using Model = std::function<double(const Eigen::VectorXd &, double)>;

    /// Residuals model(p, x_i) - y_i for Eigen's Levenberg-Marquardt.
    struct Residuals
    {
      using Scalar       = double;
      using InputType    = Eigen::VectorXd;
      using ValueType    = Eigen::VectorXd;
      using JacobianType = Eigen::MatrixXd;
      enum
      {
        InputsAtCompileTime = Eigen::Dynamic,
        ValuesAtCompileTime = Eigen::Dynamic
      };

      Model                      model;
      const std::vector<double> *x;
      const std::vector<double> *y;
      int                        n_parameters;

      int
      inputs() const
      {
        return n_parameters;
      }

      int
      values() const
      {
        return static_cast<int>(x->size());
      }

      int
      operator()(const Eigen::VectorXd &p, Eigen::VectorXd &r) const
      {
        for (std::size_t i = 0; i < x->size(); ++i)
          r[i] = model(p, (*x)[i]) - (*y)[i];
        return 0;
      }
    };

    double
    rms_residual(const Model               &model,
                 const Eigen::VectorXd     &p,
                 const std::vector<double> &x,
                 const std::vector<double> &y)
    {
      Eigen::VectorXd r(x.size());
      Residuals{model, &x, &y, int(p.size())}(p, r);
      return std::sqrt(r.squaredNorm() / x.size());
    }

    /// Refines p in place; returns the rms residual.
    double
    levenberg_marquardt(const Model               &model,
                        Eigen::VectorXd           &p,
                        const std::vector<double> &x,
                        const std::vector<double> &y)
    {
      Residuals                       residuals{model, &x, &y, int(p.size())};
      Eigen::NumericalDiff<Residuals> with_jacobian(residuals);
      Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> solver(
        with_jacobian);
      solver.parameters.xtol   = 1e-14;
      solver.parameters.ftol   = 1e-14;
      solver.parameters.maxfev = 4000;
      solver.minimize(p);
      return rms_residual(model, p, x, y);
    }

    void
    check_sizes(const std::vector<double> &x,
                const std::vector<double> &y,
                std::size_t                minimum)
    {
      if (x.size() != y.size() || x.size() < minimum)
        throw std::invalid_argument(
          "curve fit: needs at least " + std::to_string(minimum)
          + " points with matching abscissae and values");
    }

    /// Least squares of y = a + b t; returns {a, b}.
    std::pair<double, double>
    straight_line(const std::vector<double> &t, const std::vector<double> &y)
    {
      Eigen::MatrixXd A(t.size(), 2);
      Eigen::VectorXd b(t.size());
      for (std::size_t i = 0; i < t.size(); ++i)
        {
          A(i, 0) = 1.0;
          A(i, 1) = t[i];
          b[i]    = y[i];
        }
      const Eigen::Vector2d c = A.colPivHouseholderQr().solve(b);
      return {c[0], c[1]};
    }

    double
    smallest(const std::vector<double> &v)
    {
      return *std::min_element(v.begin(), v.end());
    }
  } // namespace

  CoordinationFit
  fit_coordination(const std::vector<double> &rho, const std::vector<double> &Z)
  {
    check_sizes(rho, Z, 5);
    const double rho_min = smallest(rho);
    // rho_c = rho_min - exp(s) keeps the base of the power positive.
    const Model model = [rho_min](const Eigen::VectorXd &p, double r) {
      return p[0]
             + p[1] * std::pow(r - (rho_min - std::exp(p[2])), std::exp(p[3]));
    };
    // Variable projection on a grid of (rho_c, theta): the model is linear
    // in (Z_c, Z_0) there.
    Eigen::VectorXd best(4);
    double          best_rms    = std::numeric_limits<double>::infinity();
    double          largest_gap = 0.0, largest_theta = 0.0;
    for (double gap = 1e-4; gap < 0.3; gap *= 1.5)
      for (double theta = 0.1; theta < 2.0; theta += 0.05)
        {
          largest_gap   = gap;
          largest_theta = theta;
          std::vector<double> t(rho.size());
          for (std::size_t i = 0; i < rho.size(); ++i)
            t[i] = std::pow(rho[i] - rho_min + gap, theta);
          const auto [a, b] = straight_line(t, Z);
          Eigen::VectorXd p(4);
          p << a, b, std::log(gap), std::log(theta);
          const double rms = rms_residual(model, p, rho, Z);
          if (rms < best_rms)
            {
              best_rms = rms;
              best     = p;
            }
        }
    // Levenberg-Marquardt from the best grid point; a result that leaves
    // the grid's range of exponents (theta -> 0 with Z_c -> -infinity
    // mimics a logarithm) or of critical densities is not a power law of
    // the form of Eq. (14): the grid point stands.
    Eigen::VectorXd refined = best;
    double          rms     = levenberg_marquardt(model, refined, rho, Z);
    const double    theta   = std::exp(refined[3]);
    bool            refined_stands = false;
    if (theta >= 0.1 && theta <= 2.0 && std::exp(refined[2]) < 0.3
        && rms <= best_rms)
      {
        best           = refined;
        refined_stands = true;
      }
    else
      rms = best_rms;
    CoordinationFit fit{
      best[0], best[1], rho_min - std::exp(best[2]), std::exp(best[3]), rms};
    // Where the grid point stands, it is on the edge if its exponent or
    // gap is the grid's first or last; a refined optimum is inside.
    const auto same
      = [](double a, double b) { return std::abs(a - b) <= 1e-9 * b; };
    fit.on_search_edge
      = !refined_stands
        && (same(fit.theta, 0.1) || same(fit.theta, largest_theta)
            || same(rho_min - fit.rho_c, largest_gap));
    return fit;
  }

  PunchPressureFit
  fit_punch_pressure(const std::vector<double> &rho,
                     const std::vector<double> &pressure,
                     const double               rho_c)
  {
    check_sizes(rho, pressure, 2);
    std::vector<double> log_x, log_y;
    for (std::size_t i = 0; i < rho.size(); ++i)
      if (rho[i] > rho_c && pressure[i] > 0)
        {
          log_x.push_back(std::log(rho[i] - rho_c));
          log_y.push_back(std::log(pressure[i]));
        }
    check_sizes(log_x, log_y, 2);
    const auto [a, b] = straight_line(log_x, log_y);
    const Model model = [rho_c](const Eigen::VectorXd &p, double r) {
      return std::exp(p[0]) * std::pow(std::max(r - rho_c, 0.0), p[1]);
    };
    Eigen::VectorXd p(2);
    p << a, b;
    const double rms = levenberg_marquardt(model, p, rho, pressure);
    return {std::exp(p[0]), p[1], rms};
  }

  LinearCriticalFit
  fit_linear_critical(const std::vector<double> &rho,
                      const std::vector<double> &y)
  {
    check_sizes(rho, y, 2);
    const auto [a, b] = straight_line(rho, y);
    double sum        = 0;
    for (std::size_t i = 0; i < rho.size(); ++i)
      sum += std::pow(a + b * rho[i] - y[i], 2);
    return {a + b, -a / b, std::sqrt(sum / rho.size())};
  }

  LinearCriticalFit
  fit_residual_pressure(const std::vector<double> &rho,
                        const std::vector<double> &pressure)
  {
    check_sizes(rho, pressure, 2);
    // sigma = c2 rho^2 + c1 rho with c2 = s0/(1-rc), c1 = -s0 rc/(1-rc).
    Eigen::MatrixXd A(rho.size(), 2);
    Eigen::VectorXd b(rho.size());
    for (std::size_t i = 0; i < rho.size(); ++i)
      {
        A(i, 0) = rho[i] * rho[i];
        A(i, 1) = rho[i];
        b[i]    = pressure[i];
      }
    const Eigen::Vector2d c     = A.colPivHouseholderQr().solve(b);
    const double          rho_c = -c[1] / c[0];
    return {c[0] * (1 - rho_c),
            rho_c,
            std::sqrt((A * c - b).squaredNorm() / rho.size())};
  }

  PhaniNiyogiFit
  fit_phani_niyogi(const std::vector<double> &rho, const std::vector<double> &E)
  {
    check_sizes(rho, E, 3);
    const double rho_min = smallest(rho);
    // rho_c = rho_min / (1 + exp(-s)) stays in (0, rho_min): with few,
    // nearly collinear points the unconstrained fit runs off to rho_c -> -inf.
    const auto critical
      = [rho_min](double s) { return rho_min / (1 + std::exp(-s)); };
    const Model model = [critical](const Eigen::VectorXd &p, double r) {
      const double rho_c = critical(p[2]);
      return std::exp(p[0]) * std::pow((r - rho_c) / (1 - rho_c), p[1]);
    };
    Eigen::VectorXd best(3);
    double          best_rms = std::numeric_limits<double>::infinity();
    for (double gap = 1e-4; gap < 0.99 * rho_min; gap *= 1.3)
      {
        const double        rho_c = rho_min - gap;
        std::vector<double> log_x(rho.size()), log_y(rho.size());
        for (std::size_t i = 0; i < rho.size(); ++i)
          {
            log_x[i] = std::log((rho[i] - rho_c) / (1 - rho_c));
            log_y[i] = std::log(std::max(E[i], 1e-300));
          }
        const auto [a, b] = straight_line(log_x, log_y);
        Eigen::VectorXd p(3);
        p << a, b, -std::log(rho_min / rho_c - 1);
        const double rms = rms_residual(model, p, rho, E);
        if (rms < best_rms)
          {
            best_rms = rms;
            best     = p;
          }
      }
    const double rms = levenberg_marquardt(model, best, rho, E);
    return {std::exp(best[0]), best[1], critical(best[2]), rms};
  }
} // namespace compax::dem
