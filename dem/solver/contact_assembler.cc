#include "dem/solver/contact_assembler.h"

#include "dem/numbers.h"

#include <cmath>

#include <omp.h>

namespace compax::dem
{
  ContactResponse
  contact_response(const BondedElastoplasticLaw &law,
                   const double                  gamma,
                   const ContactHistory         &h)
  {
    // Plastic loading (Gonzalez 2018 Eq. 3 with a >= a_p) written out as in
    // BondedElastoplasticLaw::response, with a^{1/m} = sqrt(a) for m = 2
    // (libm's pow dominated the profile of the residual).
    const auto  &k  = law.constants();
    const double c2 = law.c_squared();
    const double R  = k.effective_radius;
    if (gamma > 0.0 && gamma >= h.a_p * h.a_p / (2.0 * c2 * R))
      {
        const double a     = std::sqrt(2.0 * c2 * R * gamma);
        const double inv_m = 1.0 / k.plastic_exponent;
        const double a_pow_m
          = k.plastic_exponent == 2.0 ? std::sqrt(a) : std::pow(a, inv_m);
        const double n_p = k.plastic_coefficient;
        return {n_p * a * a * a_pow_m,
                n_p * (2.0 + inv_m) * c2 * R * a_pow_m,
                a};
      }
    if (h.a_p == 0.0)
      return {};
    if (k.plastic_exponent != 2.0)
      return law.response(gamma, h.a_p, h.a_B);

    // Elastic (un)loading and the solid bridge (Eq. 4), as in
    // BondedElastoplasticLaw::response, with a_p^{1/2} by sqrt.
    const double n_p      = k.plastic_coefficient;
    const double a_p      = h.a_p;
    const double root_ap  = std::sqrt(a_p);
    const double gamma_p  = a_p * a_p / (2.0 * c2 * R);
    const double alpha    = 4.0 * k.effective_modulus / (3.0 * n_p * root_ap);
    const double recovery = alpha * (gamma_p - gamma);
    const double a2       = a_p * a_p - recovery * recovery;
    if (a2 <= 0.0)
      return {};
    const double    a = std::sqrt(a2);
    const double    x = a / a_p;
    ContactResponse r;
    r.contact_radius = a;
    r.force          = 2.0 * n_p / pi * a_p * a_p * root_ap
              * (std::asin(x) - x * std::sqrt(1.0 - x * x));
    r.stiffness = 16.0 * k.effective_modulus * a / (3.0 * pi);
    if (k.fracture_toughness > 0.0 && h.a_B > 0.0
        && (a < h.a_B || !k.regularized))
      {
        const double root_a  = std::sqrt(a);
        double       scale   = 2.0 * k.fracture_toughness * std::sqrt(pi);
        double       g       = a * root_a;
        double       dg_da_a = 1.5 / root_a;
        if (k.regularized)
          {
            const double xi    = k.regularization;
            const double gap   = h.a_B - a;
            const double denom = (1.0 + xi) * h.a_B - a;
            scale *= (1.0 + xi) * (1.0 + xi);
            g *= gap / denom;
            dg_da_a = 1.5 * gap / (root_a * denom)
                      - xi * h.a_B * root_a / (denom * denom);
          }
        r.force -= scale * g;
        r.stiffness -= scale * dg_da_a * alpha * alpha * (gamma_p - gamma);
      }
    return r;
  }

  namespace
  {
    /// The law's response of a die's pair contact at overlap gamma.
    const auto pair_response = [](const PairContact &c, const double gamma) {
      return contact_response(c.law, gamma, c.history);
    };
  } // namespace

  void
  ContactAssembler::add_pair_forces_in_parallel(const Bed       &bed,
                                                Eigen::VectorXd &F,
                                                LoadedContacts  &loaded)
  {
    const int  threads = omp_get_max_threads();
    const auto size    = static_cast<Eigen::Index>(F.size());
    thread_forces.resize(threads);
    thread_loaded.assign(threads, LoadedContacts{});
    for (Eigen::VectorXd &f : thread_forces)
      f.resize(size);
#pragma omp parallel num_threads(threads)
    {
      const int        t  = omp_get_thread_num();
      Eigen::VectorXd &Ft = thread_forces[t];
      Ft.setZero();
      // Thread-local counters: neighbouring slots of one vector would
      // share a cache line and serialise the threads.
      LoadedContacts loaded_t;
      const auto     n = static_cast<std::int64_t>(bed.contacts.pairs.size());
#pragma omp for schedule(static)
      for (std::int64_t k = 0; k < n; ++k)
        add_pair_terms<false>(
          bed, k, pair_response, pattern, Ft, nullptr, loaded_t);
      thread_loaded[t] = loaded_t;
      // The loop's implicit barrier: every thread's vector is complete.
#pragma omp for schedule(static)
      for (Eigen::Index i = 0; i < size; ++i)
        for (int s = 0; s < threads; ++s)
          F[i] += thread_forces[s][i];
    }
    for (int t = 0; t < threads; ++t)
      loaded.add(thread_loaded[t]);
  }

  ContactSums
  ContactAssembler::residual(Bed                &bed,
                             const ContactModel &model,
                             Eigen::VectorXd    &F)
  {
    bed.contacts.update(bed.particles, bed.walls, model);
    return evaluate<false>(bed, F, nullptr);
  }

  ContactSums
  ContactAssembler::assemble(Bed                &bed,
                             const ContactModel &model,
                             Eigen::VectorXd    &F,
                             BlockSparseMatrix  &K)
  {
    bed.contacts.update(bed.particles, bed.walls, model);
    pattern.refresh(bed.particles.size(),
                    bed.contacts.revision(),
                    bed.contacts.pairs,
                    K);
    K.set_zero();
    return evaluate<true>(bed, F, &K);
  }

  template <bool with_stiffness>
  ContactSums
  ContactAssembler::evaluate(const Bed         &bed,
                             Eigen::VectorXd   &F,
                             BlockSparseMatrix *K)
  {
    const ParticleSystem &p = bed.particles;
    F.setZero(3 * p.size());
    ContactSums    sums;
    LoadedContacts loaded;

    const std::size_t n_pairs = bed.contacts.pairs.size();
    if (!with_stiffness && n_pairs >= parallel_pairs)
      add_pair_forces_in_parallel(bed, F, loaded);
    else
      for (std::size_t k = 0; k < n_pairs; ++k)
        add_pair_terms<with_stiffness>(
          bed, k, pair_response, pattern, F, K, loaded);

    for (const WallContact &c : bed.contacts.walls)
      {
        const WallGap g = bed.walls.gap(c.wall, p.positions[c.i], p.radii[c.i]);
        if (c.history.a_p == 0.0
            && (g.overlap <= 0.0 || g.overlap < touch_tolerance * p.radii[c.i]))
          continue;
        const ContactResponse r = contact_response(c.law, g.overlap, c.history);
        if (r.force == 0.0 && r.stiffness == 0.0)
          continue;
        F.template segment<3>(3 * c.i) -= r.force * g.normal;
        sums.wall_force[static_cast<int>(c.wall)] += r.force;
        loaded.add(r);
        if constexpr (with_stiffness)
          {
            double *blk = K->block(K->diagonal_slot(c.i));
            for (int row = 0; row < 3; ++row)
              for (int col = 0; col < 3; ++col)
                blk[3 * row + col]
                  += r.stiffness * g.normal[row] * g.normal[col];
            if (c.wall == Wall::die && g.axis_distance > 0.0)
              {
                // d(-P e_r)/dx with e_r turning: +P/r (I_xy - e_r e_r^T)
                // in F = +P e_r (the wall pushes along -e_r).
                const double s  = r.force / g.axis_distance;
                const double ex = -g.normal[0], ey = -g.normal[1];
                blk[0] += s * (1.0 - ex * ex);
                blk[1] += s * (-ex * ey);
                blk[3] += s * (-ex * ey);
                blk[4] += s * (1.0 - ey * ey);
              }
          }
      }
    loaded.report(sums);
    return sums;
  }

  template ContactSums
  ContactAssembler::evaluate<true>(const Bed &,
                                   Eigen::VectorXd &,
                                   BlockSparseMatrix *);
  template ContactSums
  ContactAssembler::evaluate<false>(const Bed &,
                                    Eigen::VectorXd &,
                                    BlockSparseMatrix *);
} // namespace compax::dem
