#include "dem/solver/lbfgs_relaxation.h"

#include "dem/parallel_particles.h"
#include "dem/solver/residual_norms.h"
#include "dem/solver/trust_region_newton.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

namespace compax::dem
{
  namespace
  {
    /// Strong Wolfe curvature parameter: a trial point is accepted once the
    /// directional derivative has dropped to this fraction of its start.
    constexpr double wolfe_curvature = 0.9;
    /// Entries of d per block of the two-loop recursion's dot products
    /// (256 particles; a bed of 6512 spheres has 26 blocks).
    constexpr Eigen::Index direction_block = 768;
    /// Beds with fewer blocks than this (parallel_particles spheres) take
    /// the plain recursion: threads would cost more than they share there
    /// (60 spheres: 2.3 us serial, 9 us on two threads; 512 spheres about
    /// even), and their paths stay those of Eigen's dot products.
    constexpr std::ptrdiff_t parallel_direction_blocks
      = 3 * parallel_particles / direction_block;
    static_assert(parallel_direction_blocks * direction_block
                    == 3 * parallel_particles,
                  "the recursion's blocks must cover parallel_particles "
                  "spheres exactly");
    /// Entries of a vector from which its updates are shared among the
    /// threads: the recursion's threshold.
    constexpr Eigen::Index parallel_entries
      = direction_block * parallel_direction_blocks;

    /// Runs update(j) for every entry j in [0, n), on every thread for a
    /// large bed. Each entry is written by its own update alone, so the
    /// result is the same on any number of threads.
    template <typename Update>
    void
    for_each_entry(const Eigen::Index n, const Update &update)
    {
#pragma omp parallel for schedule(static) if (n >= parallel_entries)
      for (Eigen::Index j = 0; j < n; ++j)
        update(j);
    }

    /// Trial points of one line search before it gives up.
    constexpr int max_trials = 20;
    /// Accepted iterations between refreshes of the preconditioner.
    constexpr int preconditioner_interval = 50;

    /// d_j = update(j) for j in [0, length), and the sum of w_j d_j in eight
    /// interleaved partial sums: independent chains, so that the additions'
    /// latency overlaps and the compiler can pack them into vector
    /// registers. The summation order is fixed by this loop alone.
    template <typename Update>
    double
    update_then_dot(const Eigen::Index length,
                    const double      *w,
                    double            *d,
                    const Update      &update)
    {
      double       partial[8] = {};
      Eigen::Index j          = 0;
      for (; j + 8 <= length; j += 8)
        for (int u = 0; u < 8; ++u)
          {
            d[j + u] = update(j + u);
            partial[u] += w[j + u] * d[j + u];
          }
      for (int u = 0; j < length; ++j, ++u)
        {
          d[j] = update(j);
          partial[u] += w[j] * d[j];
        }
      return ((partial[0] + partial[1]) + (partial[2] + partial[3]))
             + ((partial[4] + partial[5]) + (partial[6] + partial[7]));
    }
  } // namespace

  LbfgsRelaxation::LbfgsRelaxation(const int memory)
      : memory(std::max(1, memory))
      , s_history(this->memory)
      , y_history(this->memory)
      , rho(this->memory, 0.0)
      , alpha(this->memory, 0.0)
  {
  }

  double
  LbfgsRelaxation::plain_search_direction()
  {
    d = g;
    for (int k = 0; k < n_stored; ++k)
      {
        const int i = (newest - k + memory) % memory;
        alpha[i]    = rho[i] * s_history[i].dot(d);
        d.noalias() -= alpha[i] * y_history[i];
      }
    d = scaling * d.cwiseProduct(inverse_diagonal);
    for (int k = n_stored - 1; k >= 0; --k)
      {
        const int    i    = (newest - k + memory) % memory;
        const double beta = rho[i] * y_history[i].dot(d);
        d.noalias() += (alpha[i] - beta) * s_history[i];
      }
    d = -d;
    return g.dot(d);
  }

  double
  LbfgsRelaxation::search_direction()
  {
    // The two-loop recursion, in passes over the vectors that each fuse an
    // update of d with the dot product the next update needs. Each dot
    // product is summed over fixed blocks in block order, so d is the same
    // whether one thread or several share the passes (one thread is a team
    // of one: the same passes at the cost of a few barriers).
    const Eigen::Index n = g.size();
    const auto n_blocks  = static_cast<std::ptrdiff_t>((n + direction_block - 1)
                                                      / direction_block);
    if (n_blocks < parallel_direction_blocks)
      return plain_search_direction();
    d.resize(n);
    const auto pair_index
      = [this](const int k) { return (newest - k + memory) % memory; };
    const double *const M = inverse_diagonal.data();
    const double *const G = g.data();
    double *const       D = d.data();
    const auto S = [&](const int k) { return s_history[pair_index(k)].data(); };
    const auto Y = [&](const int k) { return y_history[pair_index(k)].data(); };
    const int  m = n_stored;

    // pass(update) runs update(first, length) on every block, which changes
    // d there and returns the block's term of the next dot product, and
    // returns their sum in block order. alpha_k holds the caller's alphas.
    const auto two_loop = [&](const auto &pass, double *const alpha_k) {
      // d = g, or d = -M^-1 g scaled (the preconditioned steepest descent)
      // with no pair stored.
      double dot = pass([&](const Eigen::Index f, const Eigen::Index l) {
        if (m == 0)
          return update_then_dot(l, G + f, D + f, [&](const Eigen::Index j) {
            return -scaling * (G[f + j] * M[f + j]);
          });
        return update_then_dot(l, S(0) + f, D + f, [&](const Eigen::Index j) {
          return G[f + j];
        });
      });
      // First loop, newest pair first: alpha_k = rho s_k.d, d -= alpha_k y_k;
      // after the oldest pair d is scaled by the initial inverse Hessian.
      for (int k = 0; k < m; ++k)
        {
          const double  a = alpha_k[k] = rho[pair_index(k)] * dot;
          const double *y              = Y(k);
          dot = pass([&](const Eigen::Index f, const Eigen::Index l) {
            if (k + 1 < m)
              return update_then_dot(l,
                                     S(k + 1) + f,
                                     D + f,
                                     [&](const Eigen::Index j) {
                                       return D[f + j] - a * y[f + j];
                                     });
            return update_then_dot(l, y + f, D + f, [&](const Eigen::Index j) {
              return scaling * ((D[f + j] - a * y[f + j]) * M[f + j]);
            });
          });
        }
      // Second loop, oldest pair first: d += (alpha_k - rho y_k.d) s_k; the
      // last pass negates d and returns the slope g.d.
      for (int k = m - 1; k >= 0; --k)
        {
          const double  c = alpha_k[k] - rho[pair_index(k)] * dot;
          const double *s = S(k);
          dot = pass([&](const Eigen::Index f, const Eigen::Index l) {
            if (k > 0)
              return update_then_dot(l,
                                     Y(k - 1) + f,
                                     D + f,
                                     [&](const Eigen::Index j) {
                                       return D[f + j] + c * s[f + j];
                                     });
            return update_then_dot(l, G + f, D + f, [&](const Eigen::Index j) {
              return -(D[f + j] + c * s[f + j]);
            });
          });
        }
      return dot;
    };

    const auto block_length = [n](const std::ptrdiff_t b) {
      return std::min(direction_block, n - b * direction_block);
    };
    thread_alpha.resize(static_cast<std::size_t>(memory)
                        * static_cast<std::size_t>(omp_get_max_threads()));
    for (std::vector<double> &partials : block_partials)
      partials.resize(n_blocks);
    double slope = 0.0;
#pragma omp parallel
    {
      int        pass_number = 0;
      const auto pass        = [&](const auto &update) {
        // Two buffers in turn: a thread may still sum this pass's terms
        // while another writes the next pass's.
        std::vector<double> &partials = block_partials[pass_number++ % 2];
#pragma omp for schedule(static)
        for (std::ptrdiff_t b = 0; b < n_blocks; ++b)
          partials[b] = update(b * direction_block, block_length(b));
        double sum = 0.0;
        for (const double term : partials)
          sum += term;
        return sum;
      };
      const double thread_slope
        = two_loop(pass, thread_alpha.data() + memory * omp_get_thread_num());
#pragma omp master
      slope = thread_slope;
    }
    return slope;
  }

  void
  LbfgsRelaxation::remember(Eigen::VectorXd &s_new, Eigen::VectorXd &y_new)
  {
    const double sy = s_new.dot(y_new);
    // A pair without positive curvature (a saddle, or a contact list
    // change) would make H indefinite: skip it.
    if (!(sy > 1e-12 * s_new.norm() * y_new.norm()))
      return;
    scaling = sy / y_new.dot(y_new.cwiseProduct(inverse_diagonal));
    newest  = (newest + 1) % memory;
    s_history[newest].swap(s_new);
    y_history[newest].swap(y_new);
    rho[newest] = 1.0 / sy;
    n_stored    = std::min(n_stored + 1, memory);
  }

  FireResult
  LbfgsRelaxation::relax(EquilibriumSystem &system,
                         const double       target,
                         const int          max_evaluations,
                         const double       force_floor)
  {
    const std::size_t n = system.n_particles();
    inverse_diagonal.resize(3 * n);
    for (int k = 0; k < memory; ++k)
      {
        s_history[k].resize(3 * n);
        y_history[k].resize(3 * n);
      }
    n_stored         = 0;
    newest           = -1;
    scaling          = 1.0;
    const double cap = system.skin();

    start_watching();
    FireResult result;
    assemble_inverse_diagonal(system, g, inverse_diagonal);
    int evaluations = 1, accepted = 0;
    result.assemblies = 1;
    auto x            = system.coordinates();
    for (;;)
      {
        record(result,
               relaxation_balance(g, sums, target, force_floor),
               evaluations);
        if (result.converged || result.stalled
            || evaluations >= max_evaluations)
          break;
        if (accepted > 0 && accepted % preconditioner_interval == 0)
          {
            // The seed of H only: the stored pairs stay valid.
            assemble_inverse_diagonal(system, g, inverse_diagonal);
            ++evaluations;
            ++result.assemblies;
          }
        double slope0 = search_direction();
        if (!(slope0 < 0.0))
          {
            // Not a descent direction: restart from the preconditioned
            // gradient.
            n_stored = 0;
            scaling  = 1.0;
            d        = -g.cwiseProduct(inverse_diagonal);
            slope0   = g.dot(d);
          }
        const double dmax = max_particle_norm(d);
        if (!(dmax > 0.0))
          break;
        const double a_max = cap / dmax;

        // Line search on the directional derivative phi'(a) = g(x0+a d).d.
        const Eigen::Index n_x = x.size();
        x0.resize(n_x);
        for_each_entry(n_x, [&](const Eigen::Index j) { x0[j] = x[j]; });
        double a    = std::min(1.0, a_max);
        double a_lo = 0.0, slope_lo = slope0;
        double a_hi = std::numeric_limits<double>::infinity(), slope_hi = 0.0;
        bool   found = false;
        ContactSums trial_sums;
        for (int t = 0; t < max_trials && evaluations < max_evaluations; ++t)
          {
            for_each_entry(n_x, [&](const Eigen::Index j) {
              x[j] = x0[j] + a * d[j];
            });
            trial_sums = system.residual(g_trial);
            ++evaluations;
            const double slope = g_trial.dot(d);
            if (std::abs(slope) <= wolfe_curvature * std::abs(slope0))
              {
                found = true;
                break;
              }
            if (slope < 0.0)
              {
                a_lo     = a;
                slope_lo = slope;
                if (a >= a_max)
                  {
                    found = true; // as far as a particle may move
                    break;
                  }
              }
            else
              {
                a_hi     = a;
                slope_hi = slope;
              }
            if (std::isinf(a_hi))
              a = std::min(2.0 * a, a_max);
            else
              {
                // Secant on phi', safeguarded inside the bracket.
                const double w = a_hi - a_lo;
                a              = a_lo - slope_lo * w / (slope_hi - slope_lo);
                a              = std::clamp(a, a_lo + 0.1 * w, a_hi - 0.1 * w);
              }
          }
        if (!found)
          {
            if (!(a_lo > 0.0))
              {
                x    = x0;
                sums = system.residual(g);
                ++evaluations;
                if (n_stored == 0)
                  break; // not even the preconditioned gradient descends
                n_stored = 0;
                scaling  = 1.0;
                continue;
              }
            // Every point up to a_lo descended: step there.
            a          = a_lo;
            x          = x0 + a * d;
            trial_sums = system.residual(g_trial);
            ++evaluations;
          }
        s.resize(n_x);
        y.resize(n_x);
        for_each_entry(n_x, [&](const Eigen::Index j) {
          s[j] = a * d[j];
          y[j] = g_trial[j] - g[j];
        });
        remember(s, y);
        g.swap(g_trial);
        sums = trial_sums;
        ++accepted;
      }
    result.iterations = evaluations;
    result.sums       = sums;
    return result;
  }
} // namespace compax::dem
