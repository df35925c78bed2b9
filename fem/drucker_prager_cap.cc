#include "fem/drucker_prager_cap.h"

#include "input/input_error.h"
#include "input/parameter_file.h"

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace compax::fem
{
  namespace
  {
    /// The cap function F_c(p, q, kappa) and its derivatives; kappa enters
    /// through p_a(kappa) with d p_a / d kappa = dpa.
    struct Cap
    {
      double f, fp, fq, fk, fpp, fqq, fpq, fpk, fqk;
    };

    Cap
    cap(const double         p,
        const double         q,
        const double         pa,
        const double         dpa,
        const DpcParameters &m)
    {
      const double R  = m.cap_eccentricity;
      const double a  = p - pa;
      const double b  = R * q;
      const double rc = std::max(std::sqrt(a * a + b * b), 1e-300);
      const double r3 = rc * rc * rc;
      Cap          c;
      c.f   = rc - R * (m.cohesion + pa * m.tan_friction_angle);
      c.fp  = a / rc;
      c.fq  = R * b / rc;
      c.fk  = (-a / rc - R * m.tan_friction_angle) * dpa;
      c.fpp = b * b / r3;
      c.fqq = R * R * a * a / r3;
      c.fpq = -a * b * R / r3;
      c.fpk = -b * b / r3 * dpa;
      c.fqk = R * a * b / r3 * dpa;
      return c;
    }

    /// p_a and d p_a / d kappa for the plastic compaction kappa of the
    /// increment, starting from plastic density rho_p.
    void
    transition(const DpcTable      &table,
               const DpcParameters &m,
               const double         rho_p,
               const double         kappa,
               double              &pa,
               double              &dpa)
    {
      const double rp = rho_p * std::exp(kappa);
      double       pb, dpb;
      table.cap_pressure(rp, pb, dpb);
      const double s = 1.0 + m.cap_eccentricity * m.tan_friction_angle;
      pa             = (pb - m.cap_eccentricity * m.cohesion) / s;
      dpa            = dpb * rp / s;
    }

    /// Jacobian of the cap return residual in (p, q, dlambda).
    dealii::Tensor<2, 3>
    cap_jacobian(const Cap &c, const double dl, const double K, const double G)
    {
      dealii::Tensor<2, 3> J;
      J[0][0] = 1.0 + K * dl * c.fpp - dl * c.fpk;
      J[0][1] = K * dl * c.fpq;
      J[0][2] = K * c.fp;
      J[1][0] = 3 * G * dl * (c.fpq - c.fqk / K);
      J[1][1] = 1.0 + 3 * G * dl * c.fqq;
      J[1][2] = 3 * G * c.fq;
      J[2][0] = c.fp - c.fk / K;
      J[2][1] = c.fq;
      J[2][2] = 0.0;
      return J;
    }

    /// Solves the 3x3 system J x = b.
    dealii::Tensor<1, 3>
    solve3(const dealii::Tensor<2, 3> &J, const dealii::Tensor<1, 3> &b)
    {
      return dealii::invert(J) * b;
    }
  } // namespace

  DruckerPragerCap::DruckerPragerCap(DpcTable table)
      : data(std::move(table))
  {
    data.validate();
  }

  void
  DruckerPragerCap::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("DPC table",
                      "",
                      dealii::Patterns::Anything(),
                      "CSV file with the density-dependent Drucker-Prager "
                      "Cap data, header relative_density,cohesion,"
                      "friction_angle_deg,cap_eccentricity,cap_pressure,"
                      "youngs_modulus,poisson_ratio (Pa, degrees); empty: "
                      "the built-in microcrystalline cellulose table. "
                      "Unit: file path.");
  }

  std::shared_ptr<const MaterialModel>
  DruckerPragerCap::parse_parameters(dealii::ParameterHandler &prm)
  {
    const std::string file = prm.get("DPC table");
    try
      {
        return std::make_shared<DruckerPragerCap>(
          file.empty() ? DpcTable::microcrystalline_cellulose()
                       : DpcTable::read_csv(input::resolve_input_path(file)));
      }
    catch (const std::exception &e)
      {
        input::reject_entry("Material/DPC table", file, e.what());
      }
  }

  void
  DruckerPragerCap::initialize(const double              rho,
                               dealii::ArrayView<double> h) const
  {
    std::fill(h.begin(), h.end(), 0.0);
    h[6]  = rho;
    h[13] = rho;
  }

  double
  DruckerPragerCap::cap_transition_pressure(const double rho,
                                            const double rho_p) const
  {
    const DpcParameters m = data.parameters(rho);
    double              pa, dpa;
    transition(data, m, rho_p, 0.0, pa, dpa);
    return pa;
  }

  double
  DruckerPragerCap::yield_function(const dealii::SymmetricTensor<2, 3> &sigma,
                                   const double                         rho,
                                   const double rho_p) const
  {
    const DpcParameters m = data.parameters(rho);
    const double        p = pressure(sigma), q = von_mises(sigma);
    double              pa, dpa;
    transition(data, m, rho_p, 0.0, pa, dpa);
    if (p <= pa)
      return q - p * m.tan_friction_angle - m.cohesion;
    return cap(p, q, pa, dpa, m).f;
  }

  bool
  DruckerPragerCap::evaluate(const MaterialIncrement        &inc,
                             dealii::ArrayView<const double> old_h,
                             dealii::ArrayView<double>       new_h,
                             MaterialResponse               &r) const
  {
    using dealii::SymmetricTensor;
    const double        rho_n = old_h[6], rho_p = old_h[13];
    const DpcParameters m = data.parameters(rho_n);
    const double        E = m.youngs_modulus, nu = m.poisson_ratio;
    const double        K  = E / (3.0 * (1.0 - 2.0 * nu));
    const double        G  = E / (2.0 * (1.0 + nu));
    const double        tb = m.tan_friction_angle, d = m.cohesion;

    const SymmetricTensor<2, 3> I  = dealii::unit_symmetric_tensor<3>();
    const SymmetricTensor<4, 3> Id = dealii::deviator_tensor<3>();
    const SymmetricTensor<4, 3> C
      = K * dealii::outer_product(I, I) + 2.0 * G * Id;

    const SymmetricTensor<2, 3> sig_tr
      = load(old_h, 0) + C * inc.strain_increment;
    const double                p_tr   = pressure(sig_tr);
    const SymmetricTensor<2, 3> s_tr   = dealii::deviator(sig_tr);
    const double                norm_s = s_tr.norm();
    const double                q_tr   = std::sqrt(1.5) * norm_s;
    const double                scale  = std::abs(p_tr) + q_tr + E * 1e-6;
    const bool                  has_direction = norm_s > 1e-14 * scale;
    const SymmetricTensor<2, 3> n             = has_direction
                                                  ? SymmetricTensor<2, 3>(s_tr / norm_s)
                                                  : SymmetricTensor<2, 3>();

    double pa0, dpa0;
    transition(data, m, rho_p, 0.0, pa0, dpa0);

    // Result of the return in invariants and its derivatives with respect
    // to the trial invariants.
    double p = p_tr, q = q_tr, kappa = 0.0;
    double dp_dp = 1.0, dp_dq = 0.0, dq_dp = 0.0, dq_dq = 1.0;
    bool   plastic = false, at_apex = false;

    // Corner p = p_a(kappa), q = d + p tan(beta), with the plastic
    // compaction kappa = (p_tr - p) / K that the return implies.
    auto corner = [&]() {
      double pa = pa0, dpa = dpa0;
      p = pa0;
      for (unsigned int it = 0; it < 100; ++it)
        {
          kappa = (p_tr - p) / K;
          transition(data, m, rho_p, kappa, pa, dpa);
          const double g = p - pa;
          if (std::abs(g) < 1e-12 * (scale + pa0 + d) && it > 0)
            {
              q     = d + p * tb;
              dp_dp = (dpa / K) / (1.0 + dpa / K);
              dq_dp = tb * dp_dp;
              dp_dq = 0.0;
              dq_dq = 0.0;
              return true;
            }
          p -= g / (1.0 + dpa / K);
        }
      return false;
    };

    if (p_tr > pa0)
      {
        if (cap(p_tr, q_tr, pa0, dpa0, m).f > 0.0)
          {
            plastic             = true;
            double       dl     = 0.0;
            bool         on_cap = false;
            double       pa = pa0, dpa = dpa0;
            Cap          c{};
            const double tol = 1e-12 * (scale + pa0 + d);
            for (unsigned int it = 0; it < 100; ++it)
              {
                kappa = (p_tr - p) / K;
                transition(data, m, rho_p, kappa, pa, dpa);
                c = cap(p, q, pa, dpa, m);
                const dealii::Tensor<1, 3> res({p - p_tr + K * dl * c.fp,
                                                q - q_tr + 3 * G * dl * c.fq,
                                                c.f});
                if (res.norm() < tol && it > 0)
                  {
                    on_cap = true;
                    break;
                  }
                const dealii::Tensor<1, 3> dx
                  = solve3(cap_jacobian(c, dl, K, G), -res);
                p += dx[0];
                q = std::max(0.0, q + dx[1]);
                dl += dx[2];
                if (!std::isfinite(p) || !std::isfinite(dl))
                  return false;
              }
            if (on_cap && dl >= 0.0 && p >= pa)
              {
                const dealii::Tensor<2, 3> Jinv
                  = dealii::invert(cap_jacobian(c, dl, K, G));
                // d residual / d (p_tr, q_tr)
                const dealii::Tensor<1, 3> Bp(
                  {-1.0 + dl * c.fpk, 3 * G * dl * c.fqk / K, c.fk / K});
                const dealii::Tensor<1, 3> Bq({0.0, -1.0, 0.0});
                const dealii::Tensor<1, 3> xp = -(Jinv * Bp);
                const dealii::Tensor<1, 3> xq = -(Jinv * Bq);
                dp_dp                         = xp[0];
                dq_dp                         = xp[1];
                dp_dq                         = xq[0];
                dq_dq                         = xq[1];
              }
            else if (!corner())
              return false;
          }
      }
    else if (q_tr - p_tr * tb - d > 0.0)
      {
        plastic = true;
        // Shear line with associated flow: closed-form return.
        const double D  = 3.0 * G + K * tb * tb;
        const double dl = (q_tr - p_tr * tb - d) / D;
        if (q_tr - 3.0 * G * dl > 0.0)
          {
            p     = p_tr + K * tb * dl;
            q     = q_tr - 3.0 * G * dl;
            kappa = (p_tr - p) / K;
            dp_dp = 1.0 - K * tb * tb / D;
            dp_dq = K * tb / D;
            dq_dp = 3.0 * G * tb / D;
            dq_dq = 1.0 - 3.0 * G / D;
            // The dilation shrinks the cap; past its new p_a the state
            // belongs to the corner.
            double pa, dpa;
            transition(data, m, rho_p, kappa, pa, dpa);
            if (p > pa && !corner())
              return false;
          }
        else
          {
            // Beyond the apex of the cone in tension.
            p     = -d / tb;
            q     = 0.0;
            kappa = (p_tr - p) / K;
            dp_dp = dp_dq = dq_dp = dq_dq = 0.0;
            at_apex                       = true;
          }
      }

    if (!plastic)
      {
        r.stress  = sig_tr;
        r.tangent = C;
        store(sig_tr, new_h, 0);
        for (unsigned int k = 7; k < 13; ++k)
          new_h[k] = old_h[k];
        new_h[13] = rho_p;
      }
    else
      {
        const SymmetricTensor<2, 3> s    = std::sqrt(2.0 / 3.0) * q * n;
        r.stress                         = -p * I + s;
        const SymmetricTensor<2, 3> dptr = -K * I;
        const SymmetricTensor<2, 3> dqtr = std::sqrt(6.0) * G * n;
        const SymmetricTensor<2, 3> dp   = dp_dp * dptr + dp_dq * dqtr;
        const SymmetricTensor<2, 3> dq   = dq_dp * dptr + dq_dq * dqtr;
        r.tangent                        = -dealii::outer_product(I, dp)
                    + std::sqrt(2.0 / 3.0) * dealii::outer_product(n, dq);
        if (has_direction)
          r.tangent
            += 2.0 * G * (q / q_tr) * (Id - dealii::outer_product(n, n));
        else
          r.tangent += 2.0 * G * dq_dq * Id;
        // At the apex the exact tangent vanishes: the point has failed in
        // tension and offers no stiffness at all, and a band of such points
        // (the rim of a tablet leaving the die) makes the Newton matrix
        // singular. A tenth of the elastic tangent keeps it regular; the
        // residual is unchanged, so the converged state is the same, but
        // convergence is linear while points sit at the apex.
        if (at_apex)
          r.tangent = 0.1 * C;
        store(r.stress, new_h, 0);
        const SymmetricTensor<2, 3> d_eps_p
          = -(p_tr - p) / (3.0 * K) * I + (s_tr - s) / (2.0 * G);
        store(load(old_h, 7) + d_eps_p, new_h, 7);
        new_h[13] = rho_p * std::exp(kappa);
      }
    new_h[6] = rho_n / dealii::determinant(inc.deformation_increment);
    return true;
  }

  dealii::SymmetricTensor<2, 3>
  DruckerPragerCap::stress(dealii::ArrayView<const double> h) const
  {
    return load(h, 0);
  }

  double
  DruckerPragerCap::relative_density(dealii::ArrayView<const double> h) const
  {
    return h[6];
  }

  dealii::SymmetricTensor<2, 3>
  DruckerPragerCap::plastic_strain(dealii::ArrayView<const double> h) const
  {
    return load(h, 7);
  }

  double
  DruckerPragerCap::youngs_modulus(dealii::ArrayView<const double> h) const
  {
    return data.parameters(h[6]).youngs_modulus;
  }

  void
  DruckerPragerCap::rotate(dealii::ArrayView<double>   h,
                           const dealii::Tensor<2, 3> &R) const
  {
    store(fem::rotate(load(h, 0), R), h, 0);
    store(fem::rotate(load(h, 7), R), h, 7);
  }
} // namespace compax::fem
