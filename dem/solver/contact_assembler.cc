#include "dem/solver/contact_assembler.h"

#include <cmath>

namespace compax::dem
{
  namespace
  {
    /// block += s * (a n n^T + b I)
    inline void
    add_block(double                *blk,
              const double           s,
              const double           a,
              const double           b,
              const Eigen::Vector3d &n)
    {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          blk[3 * r + c] += s * (a * n[r] * n[c] + (r == c ? b : 0.0));
    }
  } // namespace

  void
  ContactAssembler::refresh_pattern(const Bed &bed, BlockSparseMatrix &K)
  {
    if (pattern_revision == bed.contacts.revision()
        && pattern_size == bed.particles.size() && pattern_matrix == &K)
      return;
    const auto &pairs = bed.contacts.pairs;
    scratch_pairs.clear();
    scratch_pairs.reserve(pairs.size());
    for (const PairContact &c : pairs)
      scratch_pairs.emplace_back(c.i, c.j);
    K.reinit(bed.particles.size(), scratch_pairs);
    pair_slots.resize(2 * pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k)
      {
        pair_slots[2 * k]     = K.slot(pairs[k].i, pairs[k].j);
        pair_slots[2 * k + 1] = K.slot(pairs[k].j, pairs[k].i);
      }
    pattern_revision = bed.contacts.revision();
    pattern_size     = bed.particles.size();
    pattern_matrix   = &K;
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
    refresh_pattern(bed, K);
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
    ContactSums sums;
    double      sum_abs = 0.0;

    const auto &pairs = bed.contacts.pairs;
    for (std::size_t k = 0; k < pairs.size(); ++k)
      {
        const PairContact    &c     = pairs[k];
        const Eigen::Vector3d d     = p.positions[c.i] - p.positions[c.j];
        const double          dist  = d.norm();
        const double          gamma = p.radii[c.i] + p.radii[c.j] - dist;
        if (gamma > 0.0 && gamma < touch_tolerance * dist
            && c.history.a_p == 0.0)
          continue; // touching within round-off of the coordinates
        const ContactResponse r
          = c.law.response(gamma, c.history.a_p, c.history.a_B);
        if (r.force == 0.0 && r.stiffness == 0.0)
          continue;
        const Eigen::Vector3d n = d / dist;
        F.template segment<3>(3 * c.i) -= r.force * n;
        F.template segment<3>(3 * c.j) += r.force * n;
        if (r.force != 0.0)
          {
            ++sums.n_loaded;
            sum_abs += std::abs(r.force);
          }
        if constexpr (with_stiffness)
          {
            // k = P' n n^T - P/d (I - n n^T) = (P' + P/d) n n^T - P/d I
            const double a = r.stiffness + r.force / dist;
            const double b = -r.force / dist;
            add_block(K->block(K->diagonal_slot(c.i)), 1.0, a, b, n);
            add_block(K->block(K->diagonal_slot(c.j)), 1.0, a, b, n);
            add_block(K->block(pair_slots[2 * k]), -1.0, a, b, n);
            add_block(K->block(pair_slots[2 * k + 1]), -1.0, a, b, n);
          }
      }

    for (const WallContact &c : bed.contacts.walls)
      {
        const WallGap g = bed.walls.gap(c.wall, p.positions[c.i], p.radii[c.i]);
        if (g.overlap > 0.0 && g.overlap < touch_tolerance * p.radii[c.i]
            && c.history.a_p == 0.0)
          continue;
        const ContactResponse r
          = c.law.response(g.overlap, c.history.a_p, c.history.a_B);
        if (r.force == 0.0 && r.stiffness == 0.0)
          continue;
        F.template segment<3>(3 * c.i) -= r.force * g.normal;
        sums.wall_force[static_cast<int>(c.wall)] += r.force;
        if (r.force != 0.0)
          {
            ++sums.n_loaded;
            sum_abs += std::abs(r.force);
          }
        if constexpr (with_stiffness)
          {
            double *blk = K->block(K->diagonal_slot(c.i));
            add_block(blk, 1.0, r.stiffness, 0.0, g.normal);
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
    if (sums.n_loaded > 0)
      sums.mean_force = sum_abs / sums.n_loaded;
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
