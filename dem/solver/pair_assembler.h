#pragma once

#include "dem/contact/bonded_elastoplastic.h"
#include "dem/contact/particle_law.h"
#include "dem/solver/block_sparse_matrix.h"
#include "dem/solver/contact_model.h"
#include "dem/solver/contact_sums.h"
#include "dem/solver/pair_pattern.h"
#include "dem/solver/pair_terms.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <omp.h>

namespace compax::dem
{
  /// Which branch of the contact law the stiffness follows.
  enum class ContactBranch
  {
    /// The law's tangent at the current state and history (plastic where
    /// the contact is loading): the consistent tangent of the next step.
    current,
    /// Elastic unloading everywhere: contacts on the plastic branch take
    /// the unloading stiffness 16 E* a / (3 pi) (the elastic moduli).
    unloading
  };

  /// The elastic unloading stiffness 16 E* a / (3 pi) of a contact of
  /// radius a [N/m].
  double
  unloading_stiffness(const BondedElastoplasticLaw &law, double a);

  /// Any particle law's response: the law's own evaluate() (a direct
  /// call: the laws are final); the bonded law's response() without the
  /// variant dispatch, which its hot loops measurably pay.
  inline ContactResponse
  contact_response(const ParticleLaw    &law,
                   const double          gamma,
                   const ContactHistory &history)
  {
    if (const auto *bonded = std::get_if<BondedElastoplasticLaw>(&law))
      return bonded->response(gamma,
                              BondedElastoplasticLaw::a_p(history),
                              BondedElastoplasticLaw::a_B(history));
    return law_response(law, gamma, history);
  }

  /// The response of a contact (a die's or a periodic cell's) at overlap
  /// gamma on the given branch: the law's, with the stiffness of elastic
  /// unloading (ContactLaw::unloading_stiffness(); 16 E* a / (3 pi) of a
  /// bonded contact on its plastic branch) where `unloading` is asked.
  template <typename Contact>
  inline ContactResponse
  contact_response(const Contact      &c,
                   const double        gamma,
                   const ContactBranch branch)
  {
    ContactResponse r = contact_response(c.law, gamma, c.history);
    if (branch != ContactBranch::unloading)
      return r;
    if (const auto *bonded = std::get_if<BondedElastoplasticLaw>(&c.law))
      {
        if (r.contact_radius > 0.0
            && r.contact_radius >= BondedElastoplasticLaw::a_p(c.history))
          r.stiffness = unloading_stiffness(*bonded, r.contact_radius);
      }
    else
      r.stiffness = unloading_stiffness(c.law, gamma, c.history);
    return r;
  }

  /// The wall terms of a bed without walls (a periodic cell): none. A bed
  /// in a die has its own (contact_assembler.h).
  template <bool with_stiffness, typename BedType>
  inline void
  add_wall_terms(const BedType &,
                 Eigen::VectorXd &,
                 BlockSparseMatrix *,
                 ContactSums &,
                 LoadedContacts &,
                 std::vector<WallTerm> &)
  {
  }

  /**
   * Beds with at least this many candidate pairs evaluate the pairs of a
   * residual, and of an assembly with the stiffness, on every OpenMP thread
   * (PairAssembler::residual(), PairAssembler::assemble()). Below it the
   * threads' start costs about what they save. A bed type may set its own.
   */
  template <typename BedType>
  inline constexpr std::size_t parallel_residual_pairs = 20000;

  /**
   * Residual and stiffness of the static equilibrium of Gonzalez 2018,
   * Eq. (12), of a bed at fixed walls or lattice and fixed internal
   * variables: ContactAssembler for a die's Bed, PeriodicAssembler for a
   * PeriodicBed.
   *
   * The residual is the out-of-balance internal force
   * F_i = - sum_j P_ij n_ij (n_ij = d_ij/|d_ij|, d_ij the branch vector,
   * to the contact's image in a periodic cell), the gradient of the bed's
   * stored energy, so that equilibrium is F = 0 and K = dF/dx is
   * symmetric. A pair contributes the block k = P' n n^T - P/d (I - n n^T)
   * to (i,i) and (j,j) and -k to (i,j) and (j,i) (add_pair_terms(); a pair
   * touching through several images adds all of them to the same blocks),
   * a wall its own terms (add_wall_terms()). What depends on the bed comes
   * from overloads for its type: update_contacts(), branch_vector(),
   * contact_response() and add_wall_terms().
   */
  template <typename BedType>
  class PairAssembler
  {
  public:
    static constexpr std::size_t parallel_pairs
      = parallel_residual_pairs<BedType>;

    /// F only (refreshes the contact list if needed).
    ContactSums
    residual(BedType &bed, const ContactModel &model, Eigen::VectorXd &F);

    /// F and K on the given branch of the law; the pattern of K is rebuilt
    /// only when the contact list changed.
    ContactSums
    assemble(BedType            &bed,
             const ContactModel &model,
             Eigen::VectorXd    &F,
             BlockSparseMatrix  &K,
             ContactBranch       branch = ContactBranch::current);

  private:
    template <bool with_stiffness>
    ContactSums
    evaluate(const BedType     &bed,
             Eigen::VectorXd   &F,
             BlockSparseMatrix *K,
             ContactBranch      branch);

    /// The pairs' terms into F (and K), one pair after the other in list
    /// order.
    template <bool with_stiffness, typename Response>
    void
    add_pairs_in_order(const BedType     &bed,
                       const Response    &response,
                       Eigen::VectorXd   &F,
                       BlockSparseMatrix *K,
                       LoadedContacts    &loaded);

    /// The pairs' forces into F on every thread (residual only).
    template <typename Response>
    void
    add_pair_forces_in_parallel(const BedType   &bed,
                                const Response  &response,
                                Eigen::VectorXd &F,
                                LoadedContacts  &loaded);

    /// The pairs' forces into F and their blocks into K on every thread:
    /// add_pairs_in_order<true>() to the bit.
    template <typename Response>
    void
    add_pair_terms_in_parallel(const BedType     &bed,
                               const Response    &response,
                               Eigen::VectorXd   &F,
                               BlockSparseMatrix &K,
                               LoadedContacts    &loaded);

    /**
     * The two passes of a threaded evaluation, which make its sums
     * independent of the number of threads: compute_pair_terms() on every
     * thread, then, after its barrier, @p particle_pass(), an orphaned
     * `omp for` over the particles that sums each one's pairs in list
     * order. The blocks' counts of loaded contacts are added to @p loaded
     * in block order. Per-pair buffers are resized, so they allocate only
     * when the list grew.
     */
    template <bool with_stiffness, typename Response, typename ParticlePass>
    void
    in_two_passes(const BedType      &bed,
                  const Response     &response,
                  LoadedContacts     &loaded,
                  const ParticlePass &particle_pass);

    /// Pair k's terms on every thread into pair_force[k] (and, with
    /// stiffness, pair_adds[k] and pair_block[k]); each block of the
    /// loaded-contact count into block_loaded. Called inside a parallel
    /// region: the caller's threads share the pairs.
    template <bool with_stiffness, typename Response>
    void
    compute_pair_terms(const BedType &bed, const Response &response);

    /// Entry e of `incidence` as the force it adds to its particle: -P n
    /// of its pair on particle i, +P n on particle j. f + (-P n) is
    /// f - P n to the bit: a sign, not a branch.
    Eigen::Vector3d
    signed_pair_force(const std::uint32_t e) const
    {
      constexpr double sign[2] = {-1.0, 1.0};
      return sign[e & 1u] * pair_force[e >> 1];
    }

    /// Rebuilds `incidence` where the contact list changed.
    template <typename Pairs>
    void
    refresh_incidence(std::size_t   n_particles,
                      std::uint64_t revision,
                      const Pairs  &pairs);

    PairPattern pattern;
    /// Pair k's force on its particle j, P n [N] (zero where the pair
    /// carries nothing), of the last parallel residual.
    std::vector<Eigen::Vector3d> pair_force;
    /// Pair k's stiffness block k (PairBlock::entries()) of the last
    /// parallel assembly; pair_adds[k]: whether pair k adds anything
    /// (pair_response()).
    std::vector<std::array<double, 9>> pair_block;
    std::vector<char>                  pair_adds;
    /// Block b of the count of loaded contacts (starts_loaded_block()):
    /// pairs block_first[b] to block_first[b + 1] - 1; and its count in the
    /// last parallel residual.
    std::vector<std::size_t>    block_first;
    std::vector<LoadedContacts> block_loaded;
    /// Particle p's pairs in list order: entries incidence_first[p] to
    /// incidence_first[p + 1] - 1 of `incidence`, each 2k + 1 where p is
    /// pair k's particle j and 2k where it is its particle i. Summing a
    /// particle's forces in this order is the serial loop's sum.
    std::vector<std::uint32_t> incidence_first;
    std::vector<std::uint32_t> incidence;
    std::uint64_t              incidence_revision = ~std::uint64_t(0);
    std::size_t                incidence_pairs    = 0;
    /// The wall contacts' terms of the last evaluation (a die's bed).
    std::vector<WallTerm> wall_terms;
  };

  template <typename BedType>
  ContactSums
  PairAssembler<BedType>::residual(BedType            &bed,
                                   const ContactModel &model,
                                   Eigen::VectorXd    &F)
  {
    update_contacts(bed, model);
    return evaluate<false>(bed, F, nullptr, ContactBranch::current);
  }

  template <typename BedType>
  ContactSums
  PairAssembler<BedType>::assemble(BedType            &bed,
                                   const ContactModel &model,
                                   Eigen::VectorXd    &F,
                                   BlockSparseMatrix  &K,
                                   const ContactBranch branch)
  {
    update_contacts(bed, model);
    pattern.refresh(bed.particles.size(),
                    bed.contacts.revision(),
                    bed.contacts.pairs,
                    K);
    return evaluate<true>(bed, F, &K, branch);
  }

  template <typename BedType>
  template <bool with_stiffness>
  ContactSums
  PairAssembler<BedType>::evaluate(const BedType      &bed,
                                   Eigen::VectorXd    &F,
                                   BlockSparseMatrix  *K,
                                   const ContactBranch branch)
  {
    ContactSums       sums;
    LoadedContacts    loaded;
    const std::size_t n_pairs = bed.contacts.pairs.size();
    const bool        in_parallel
      = n_pairs >= parallel_pairs && omp_get_max_threads() > 1;
    // The threaded passes write every particle's sum into F; the serial
    // loop adds into it.
    if (in_parallel)
      F.resize(3 * bed.particles.size());
    else
      F.setZero(3 * bed.particles.size());
    if constexpr (!with_stiffness)
      {
        // A residual is on the current branch. One thread sums the pairs
        // in list order directly: the parallel sum to the bit.
        const auto response = [](const auto &c, const double gamma) {
          return contact_response(c, gamma, ContactBranch::current);
        };
        if (in_parallel)
          add_pair_forces_in_parallel(bed, response, F, loaded);
        else
          add_pairs_in_order<false>(bed, response, F, nullptr, loaded);
      }
    else
      {
        const auto response = [branch](const auto &c, const double gamma) {
          return contact_response(c, gamma, branch);
        };
        if (in_parallel)
          add_pair_terms_in_parallel(bed, response, F, *K, loaded);
        else
          {
            K->set_zero();
            add_pairs_in_order<true>(bed, response, F, K, loaded);
          }
      }
    add_wall_terms<with_stiffness>(bed, F, K, sums, loaded, wall_terms);
    loaded.report(sums);
    return sums;
  }

  template <typename BedType>
  template <typename Pairs>
  void
  PairAssembler<BedType>::refresh_incidence(const std::size_t   n_particles,
                                            const std::uint64_t revision,
                                            const Pairs        &pairs)
  {
    if (revision == incidence_revision && pairs.size() == incidence_pairs
        && incidence_first.size() == n_particles + 1)
      return;
    // Counting sort of the pairs' two ends by particle, in list order.
    incidence_first.assign(n_particles + 1, 0);
    for (const auto &c : pairs)
      {
        ++incidence_first[c.i + 1];
        ++incidence_first[c.j + 1];
      }
    for (std::size_t p = 0; p < n_particles; ++p)
      incidence_first[p + 1] += incidence_first[p];
    incidence.resize(2 * pairs.size());
    std::vector<std::uint32_t> next(incidence_first.begin(),
                                    incidence_first.end() - 1);
    for (std::size_t k = 0; k < pairs.size(); ++k)
      {
        const auto side_i             = static_cast<std::uint32_t>(2 * k);
        incidence[next[pairs[k].i]++] = side_i;
        incidence[next[pairs[k].j]++] = side_i + 1;
      }
    block_first.assign(1, 0);
    for (std::size_t k = 1; k < pairs.size(); ++k)
      if (starts_loaded_block(pairs[k - 1], pairs[k]))
        block_first.push_back(k);
    block_first.push_back(pairs.size());
    incidence_revision = revision;
    incidence_pairs    = pairs.size();
  }

  template <typename BedType>
  template <bool with_stiffness, typename Response>
  void
  PairAssembler<BedType>::add_pairs_in_order(const BedType     &bed,
                                             const Response    &response,
                                             Eigen::VectorXd   &F,
                                             BlockSparseMatrix *K,
                                             LoadedContacts    &loaded)
  {
    const auto       &pairs   = bed.contacts.pairs;
    const std::size_t n_pairs = pairs.size();
    LoadedContacts    block;
    for (std::size_t k = 0; k < n_pairs; ++k)
      {
        add_pair_terms<with_stiffness>(bed, k, response, pattern, F, K, block);
        if (k + 1 == n_pairs || starts_loaded_block(pairs[k], pairs[k + 1]))
          {
            loaded.add(block);
            block = LoadedContacts{};
          }
      }
  }

  template <typename BedType>
  template <typename Response>
  void
  PairAssembler<BedType>::add_pair_forces_in_parallel(const BedType   &bed,
                                                      const Response  &response,
                                                      Eigen::VectorXd &F,
                                                      LoadedContacts  &loaded)
  {
    // Two passes, so that F does not depend on the number of threads: the
    // pairs' forces on any thread, then each particle's sum of its pairs'
    // forces in list order, which is add_pairs_in_order()'s sum to the bit.
    const auto n = static_cast<std::ptrdiff_t>(bed.particles.size());
    in_two_passes<false>(bed, response, loaded, [&] {
      // Every pair's force is known (the loop's barrier). Each particle's
      // sum is a chain of dependent additions: two particles at a time, so
      // that the two chains overlap.
      const auto pairs_of_particles = (n + 1) / 2;
#pragma omp for schedule(static)
      for (std::ptrdiff_t q = 0; q < pairs_of_particles; ++q)
        {
          const std::ptrdiff_t p0 = 2 * q, p1 = std::min(p0 + 1, n - 1);
          std::uint32_t        e0 = incidence_first[p0],
                        end0      = incidence_first[p0 + 1];
          std::uint32_t e1        = p1 > p0 ? incidence_first[p1] : end0,
                        end1      = p1 > p0 ? incidence_first[p1 + 1] : end0;
          Eigen::Vector3d f0 = Eigen::Vector3d::Zero(), f1 = f0;
          for (; e0 < end0 && e1 < end1; ++e0, ++e1)
            {
              f0 += signed_pair_force(incidence[e0]);
              f1 += signed_pair_force(incidence[e1]);
            }
          for (; e0 < end0; ++e0)
            f0 += signed_pair_force(incidence[e0]);
          for (; e1 < end1; ++e1)
            f1 += signed_pair_force(incidence[e1]);
          F.template segment<3>(3 * p0) = f0;
          if (p1 > p0)
            F.template segment<3>(3 * p1) = f1;
        }
    });
  }

  template <typename BedType>
  template <bool with_stiffness, typename Response, typename ParticlePass>
  void
  PairAssembler<BedType>::in_two_passes(const BedType      &bed,
                                        const Response     &response,
                                        LoadedContacts     &loaded,
                                        const ParticlePass &particle_pass)
  {
    const std::size_t n_pairs = bed.contacts.pairs.size();
    refresh_incidence(bed.particles.size(),
                      bed.contacts.revision(),
                      bed.contacts.pairs);
    pair_force.resize(n_pairs);
    if constexpr (with_stiffness)
      {
        pair_block.resize(n_pairs);
        pair_adds.resize(n_pairs);
      }
    block_loaded.resize(block_first.size() - 1);
#pragma omp parallel
    {
      compute_pair_terms<with_stiffness>(bed, response);
      particle_pass();
    }
    for (const LoadedContacts &block : block_loaded)
      loaded.add(block);
  }

  template <typename BedType>
  template <bool with_stiffness, typename Response>
  void
  PairAssembler<BedType>::compute_pair_terms(const BedType  &bed,
                                             const Response &response)
  {
    const auto blocks = static_cast<std::ptrdiff_t>(block_first.size() - 1);
#pragma omp for schedule(static)
    for (std::ptrdiff_t b = 0; b < blocks; ++b)
      {
        LoadedContacts block;
        for (std::size_t k = block_first[b]; k < block_first[b + 1]; ++k)
          {
            if constexpr (!with_stiffness)
              pair_force[k] = pair_force_terms(bed, k, response, block);
            else
              {
                Eigen::Vector3d n;
                double          dist;
                ContactResponse r;
                pair_adds[k] = pair_response(bed, k, response, n, dist, r);
                if (!pair_adds[k])
                  continue;
                pair_force[k] = r.force * n;
                PairBlock(r, dist).entries(n, pair_block[k].data());
                block.add(r);
              }
          }
        block_loaded[b] = block;
      }
  }

  template <typename BedType>
  template <typename Response>
  void
  PairAssembler<BedType>::add_pair_terms_in_parallel(const BedType   &bed,
                                                     const Response  &response,
                                                     Eigen::VectorXd &F,
                                                     BlockSparseMatrix &K,
                                                     LoadedContacts    &loaded)
  {
    // As add_pair_forces_in_parallel(), with the blocks: each particle
    // clears its own row of K (its diagonal block and its blocks (p, q)),
    // which no other particle writes, and sums its pairs' terms into it in
    // list order, so the sums are add_pairs_in_order<true>()'s to the bit
    // on any number of threads. A pair that adds nothing is skipped, as
    // there.
    const auto n = static_cast<std::ptrdiff_t>(bed.particles.size());
    in_two_passes<true>(bed, response, loaded, [&] {
#pragma omp for schedule(static)
      for (std::ptrdiff_t p = 0; p < n; ++p)
        {
          K.set_row_zero(p);
          Eigen::Vector3d f        = Eigen::Vector3d::Zero();
          double *const   diagonal = K.block(K.diagonal_slot(p));
          for (std::uint32_t e = incidence_first[p]; e < incidence_first[p + 1];
               ++e)
            {
              const std::uint32_t side = incidence[e];
              const std::size_t   k    = side >> 1;
              if (!pair_adds[k])
                continue;
              f += signed_pair_force(side);
              // +k on the diagonal block, -k on (p, q): scatter_pair()'s
              // sign * k to the bit.
              const double *const k_entries = pair_block[k].data();
              double *const       off_diagonal
                = K.block((side & 1u) ? pattern.ji(k) : pattern.ij(k));
              for (int m = 0; m < 9; ++m)
                {
                  diagonal[m] += k_entries[m];
                  off_diagonal[m] -= k_entries[m];
                }
            }
          F.template segment<3>(3 * p) = f;
        }
    });
  }
} // namespace compax::dem
