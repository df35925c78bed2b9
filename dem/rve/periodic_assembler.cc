#include "dem/rve/periodic_assembler.h"

#include "dem/numbers.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/pair_terms.h"

#include <cmath>

namespace compax::dem
{
  ContactResponse
  periodic_contact_response(const PeriodicContact &c,
                            const double           gamma,
                            const ContactBranch    branch)
  {
    ContactResponse r = contact_response(c.law, gamma, c.history);
    if (branch == ContactBranch::unloading && r.contact_radius > 0.0
        && r.contact_radius >= c.history.a_p)
      {
        r.stiffness = 16.0 * c.law.constants().effective_modulus
                      * r.contact_radius / (3.0 * pi);
      }
    return r;
  }

  ContactSums
  PeriodicAssembler::residual(PeriodicBed        &bed,
                              const ContactModel &model,
                              Eigen::VectorXd    &F)
  {
    bed.contacts.update(bed.particles, bed.cell, model);
    return evaluate<false>(bed, F, nullptr, ContactBranch::current);
  }

  ContactSums
  PeriodicAssembler::assemble(PeriodicBed        &bed,
                              const ContactModel &model,
                              Eigen::VectorXd    &F,
                              BlockSparseMatrix  &K,
                              const ContactBranch branch)
  {
    bed.contacts.update(bed.particles, bed.cell, model);
    pattern.refresh(bed.particles.size(),
                    bed.contacts.revision(),
                    bed.contacts.pairs,
                    K);
    K.set_zero();
    return evaluate<true>(bed, F, &K, branch);
  }

  template <bool with_stiffness>
  ContactSums
  PeriodicAssembler::evaluate(const PeriodicBed  &bed,
                              Eigen::VectorXd    &F,
                              BlockSparseMatrix  *K,
                              const ContactBranch branch)
  {
    F.setZero(3 * bed.particles.size());
    const auto response
      = [branch](const PeriodicContact &c, const double gamma) {
          return periodic_contact_response(c, gamma, branch);
        };
    LoadedContacts loaded;
    for (std::size_t k = 0; k < bed.contacts.pairs.size(); ++k)
      add_pair_terms<with_stiffness>(bed, k, response, pattern, F, K, loaded);
    ContactSums sums;
    loaded.report(sums);
    return sums;
  }

  template ContactSums
  PeriodicAssembler::evaluate<true>(const PeriodicBed &,
                                    Eigen::VectorXd &,
                                    BlockSparseMatrix *,
                                    ContactBranch);
  template ContactSums
  PeriodicAssembler::evaluate<false>(const PeriodicBed &,
                                     Eigen::VectorXd &,
                                     BlockSparseMatrix *,
                                     ContactBranch);
} // namespace compax::dem
