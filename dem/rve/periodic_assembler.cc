#include "dem/rve/periodic_assembler.h"

#include "dem/numbers.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/pair_block.h"

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
    const ParticleSystem &p = bed.particles;
    F.setZero(3 * p.size());
    ContactSums sums;
    double      sum_abs = 0.0;
    const auto &pairs   = bed.contacts.pairs;
    for (std::size_t k = 0; k < pairs.size(); ++k)
      {
        const PeriodicContact &c     = pairs[k];
        const Eigen::Vector3d  d     = branch_vector(p, bed.cell, c);
        const double           dist  = d.norm();
        const double           gamma = p.radii[c.i] + p.radii[c.j] - dist;
        if (c.history.a_p == 0.0 && gamma <= 0.0)
          continue; // virgin and apart (most candidates of the list)
        const ContactResponse r = periodic_contact_response(c, gamma, branch);
        if (r.force == 0.0 && r.stiffness == 0.0)
          continue;
        const Eigen::Vector3d n = d / dist;
        scatter_pair(F,
                     with_stiffness ? K : nullptr,
                     c.i,
                     c.j,
                     with_stiffness ? pattern.ij(k) : 0,
                     with_stiffness ? pattern.ji(k) : 0,
                     n,
                     dist,
                     r);
        if (r.force != 0.0)
          {
            ++sums.n_loaded;
            sum_abs += std::abs(r.force);
          }
      }
    if (sums.n_loaded > 0)
      sums.mean_force = sum_abs / sums.n_loaded;
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
