#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_sums.h"
#include "dem/solver/history_update.h"
#include "dem/solver/pair_assembler.h"
#include "dem/solver/pair_terms.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace compax::dem
{
  /// Wall contacts from which their gaps and responses are computed on
  /// every thread. Only the die wall's take a square root (hypot), so a
  /// short list is cheaper on one thread than a parallel region's start.
  inline constexpr std::ptrdiff_t parallel_wall_contacts = 512;

  /// Wall contact c's gap and response; a zero response where a virgin
  /// contact is apart (no law call).
  inline WallTerm
  wall_term(const Bed &bed, const WallContact &c)
  {
    const ParticleSystem &p = bed.particles;
    WallTerm              t;
    t.gap            = bed.walls.gap(c.wall, p.positions[c.i], p.radii[c.i]);
    const bool apart = !has_history(c.history)
                       && (t.gap.overlap <= 0.0
                           || t.gap.overlap < touch_tolerance * p.radii[c.i]);
    if (!apart)
      t.response = contact_response(c.law, t.gap.overlap, c.history);
    return t;
  }

  /**
   * Adds the wall contacts of a bed in a die to F (their forces also to
   * sums.wall_force) and, with stiffness, to the diagonal blocks of K: a
   * punch contributes P' n n^T; the die wall also P/r (I - e_r e_r^T)
   * restricted to the horizontal plane, because its normal turns with the
   * particle. The gaps and responses (the square roots and the law) are
   * computed on every thread into @p terms; one thread then adds them in
   * list order, so F, K and the sums are the same on any number of
   * threads.
   */
  template <bool with_stiffness>
  inline void
  add_wall_terms(const Bed             &bed,
                 Eigen::VectorXd       &F,
                 BlockSparseMatrix     *K,
                 ContactSums           &sums,
                 LoadedContacts        &loaded,
                 std::vector<WallTerm> &terms)
  {
    const std::vector<WallContact> &walls = bed.contacts.walls;
    const auto n = static_cast<std::ptrdiff_t>(walls.size());
    terms.resize(walls.size());
#pragma omp parallel for schedule(static) if (n >= parallel_wall_contacts)
    for (std::ptrdiff_t k = 0; k < n; ++k)
      terms[k] = wall_term(bed, walls[k]);

    for (std::ptrdiff_t k = 0; k < n; ++k)
      {
        const WallContact     &c = walls[k];
        const WallGap         &g = terms[k].gap;
        const ContactResponse &r = terms[k].response;
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
  }

} // namespace compax::dem
