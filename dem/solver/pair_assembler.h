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
                 LoadedContacts &)
  {
  }

  /**
   * Beds with at least this many candidate pairs evaluate the pairs of a
   * residual on every OpenMP thread, each into its own force vector, and
   * sum those in thread order (the same result for the same thread
   * count). Below it the threads' start and the sum of their vectors cost
   * about what they save. A bed type may set its own.
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

    /// The pairs' forces into F on every thread (residual only).
    void
    add_pair_forces_in_parallel(const BedType   &bed,
                                Eigen::VectorXd &F,
                                LoadedContacts  &loaded);

    PairPattern pattern;
    /// Per-thread force vectors and counts of add_pair_forces_in_parallel,
    /// kept between calls so that a residual allocates nothing.
    std::vector<Eigen::VectorXd> thread_forces;
    std::vector<LoadedContacts>  thread_loaded;
    /// Thread t sums pairs thread_first[t] to thread_first[t + 1] - 1.
    std::vector<std::size_t> thread_first;
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
    K.set_zero();
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
    F.setZero(3 * bed.particles.size());
    ContactSums       sums;
    LoadedContacts    loaded;
    const std::size_t n_pairs = bed.contacts.pairs.size();
    if (!with_stiffness && n_pairs >= parallel_pairs)
      add_pair_forces_in_parallel(bed, F, loaded);
    else
      {
        const auto response = [branch](const auto &c, const double gamma) {
          return contact_response(c, gamma, branch);
        };
        for (std::size_t k = 0; k < n_pairs; ++k)
          add_pair_terms<with_stiffness>(
            bed, k, response, pattern, F, K, loaded);
      }
    add_wall_terms<with_stiffness>(bed, F, K, sums, loaded);
    loaded.report(sums);
    return sums;
  }

  template <typename BedType>
  void
  PairAssembler<BedType>::add_pair_forces_in_parallel(const BedType   &bed,
                                                      Eigen::VectorXd &F,
                                                      LoadedContacts  &loaded)
  {
    const auto response = [](const auto &c, const double gamma) {
      return contact_response(c, gamma, ContactBranch::current);
    };
    const int  threads = omp_get_max_threads();
    const auto size    = static_cast<Eigen::Index>(F.size());
    thread_forces.resize(threads);
    thread_loaded.assign(threads, LoadedContacts{});
    for (Eigen::VectorXd &f : thread_forces)
      f.resize(size);
    // Thread t sums the pairs whose first particle is in the t-th share of
    // the particles (the list is sorted by it), so that which thread sums a
    // pair, and so the rounding, does not depend on the other pairs listed:
    // the same with or without pairs that carry nothing (a list's dormant
    // pairs, a resumed run's fresh list). The boundaries only ever grow,
    // so every pair is summed once even in an unsorted list.
    const auto &pairs = bed.contacts.pairs;
    thread_first.assign(threads + 1, pairs.size());
    thread_first[0] = 0;
    for (int t = 1; t < threads; ++t)
      {
        const auto first_particle = static_cast<std::uint32_t>(
          bed.particles.size() * static_cast<std::size_t>(t) / threads);
        const auto split = std::partition_point(pairs.begin(),
                                                pairs.end(),
                                                [&](const auto &c) {
                                                  return c.i < first_particle;
                                                });
        thread_first[t]
          = std::max(thread_first[t - 1],
                     static_cast<std::size_t>(split - pairs.begin()));
      }
#pragma omp parallel num_threads(threads)
    {
      const int        t  = omp_get_thread_num();
      Eigen::VectorXd &Ft = thread_forces[t];
      Ft.setZero();
      // Thread-local counters: neighbouring slots of one vector would
      // share a cache line and serialise the threads.
      LoadedContacts loaded_t;
      for (std::size_t k = thread_first[t]; k < thread_first[t + 1]; ++k)
        add_pair_terms<false>(bed, k, response, pattern, Ft, nullptr, loaded_t);
      thread_loaded[t] = loaded_t;
#pragma omp barrier
      // Every thread's vector is complete.
#pragma omp for schedule(static)
      for (Eigen::Index i = 0; i < size; ++i)
        for (int s = 0; s < threads; ++s)
          F[i] += thread_forces[s][i];
    }
    for (int t = 0; t < threads; ++t)
      loaded.add(thread_loaded[t]);
  }
} // namespace compax::dem
