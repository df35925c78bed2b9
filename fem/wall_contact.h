#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>

namespace compax::fem
{
  /// Traction on the body at one contact point and its derivative.
  template <int dim>
  struct WallContactResponse
  {
    /// Traction exerted by the wall on the body [Pa].
    dealii::Tensor<1, dim> traction;
    /// d traction / d displacement increment [Pa/m].
    dealii::Tensor<2, dim> tangent;
    /// Tangential (friction) part of the traction: the new history [Pa].
    dealii::Tensor<1, dim> friction;
    /// Contact pressure p >= 0 [Pa].
    double pressure = 0.0;
    /// Whether the point sticks (false: slides, or no contact).
    bool stick = false;
  };

  /**
   * Penalty contact of a body point with a rigid flat or cylindrical wall
   * (die wall, punch face), with regularised Coulomb friction. The choice
   * of a penalty method (not Lagrange multipliers) keeps the unknowns those
   * of the displacement field and lets contact open and close freely on
   * unloading and ejection; the penetration at the wall is pressure /
   * eps_n, made negligible by scaling eps_n with the stiffness of the
   * compact (TabletSolver).
   *
   * Normal: gap g = gap0 - du . n (n: unit normal out of the body, into
   * the wall); p = eps_n max(0, -g); traction -p n.
   * Friction (elastic-predictor / slip-corrector return on the Coulomb
   * cone, like plasticity): trial t = t_old - eps_t (I - n n) du; stick if
   * |t| <= mu p, else t = mu p t/|t|. The tangent is exact (non-symmetric
   * when sliding).
   *
   * @param n unit normal out of the body at the point
   * @param gap0 gap at the start of the increment [m] (negative: overlap)
   * @param du displacement increment of the point [m]
   * @param friction_old committed tangential traction [Pa]
   * @param eps_n, eps_t normal and tangential penalty [Pa/m]
   * @param mu Coulomb friction coefficient [-]
   */
  template <int dim>
  WallContactResponse<dim>
  wall_contact(const dealii::Tensor<1, dim> &n,
               const double                  gap0,
               const dealii::Tensor<1, dim> &du,
               const dealii::Tensor<1, dim> &friction_old,
               const double                  eps_n,
               const double                  eps_t,
               const double                  mu)
  {
    WallContactResponse<dim> r;
    const double             g = gap0 - du * n;
    if (g >= 0.0)
      return r;
    r.pressure               = -eps_n * g;
    dealii::Tensor<2, dim> P = dealii::unit_symmetric_tensor<dim>();
    P -= dealii::outer_product(n, n);
    // Normal part: traction -p n, dp/ddu = eps_n n.
    r.tangent = -eps_n * dealii::outer_product(n, n);
    if (mu > 0.0)
      {
        const dealii::Tensor<1, dim> trial
          = P * friction_old - eps_t * (P * du);
        const double norm  = trial.norm();
        const double limit = mu * r.pressure;
        if (norm <= limit)
          {
            r.stick    = true;
            r.friction = trial;
            r.tangent -= eps_t * P;
          }
        else
          {
            const dealii::Tensor<1, dim> m = trial / norm;
            r.friction                     = limit * m;
            r.tangent += mu * eps_n * dealii::outer_product(m, n);
            dealii::Tensor<2, dim> Q = P - dealii::outer_product(m, m);
            r.tangent -= (limit / norm) * eps_t * (Q * P);
          }
      }
    r.traction = -r.pressure * n + r.friction;
    return r;
  }
} // namespace compax::fem
