#pragma once

#include "dem/solver/contact_model.h"
#include "dem/solver/equilibrium_system.h"
#include "dem/solver/step_limits.h"

#include <Eigen/Core>

namespace compax::dem
{
  /**
   * A bed of contacts as an EquilibriumSystem: the particles of `bed` with
   * the contact law of a ContactModel, assembled by an `Assembler`
   * (ContactAssembler for a die's Bed, PeriodicAssembler for a
   * PeriodicBed). Holds references only; the assembler keeps the stiffness
   * pattern between calls.
   *
   * What differs between the beds comes from overloads found for the bed
   * type: branch_vector(bed, contact), the centre-to-centre vector of a
   * pair (to the contact's image in a periodic cell), and
   * limit_wall_closing(), the rigid walls' part of limit_closing().
   */
  template <typename BedType, typename Assembler>
  class ContactBedSystem final : public EquilibriumSystem
  {
  public:
    ContactBedSystem(BedType            &bed,
                     const ContactModel &model,
                     Assembler          &assembler)
        : bed(bed)
        , model(model)
        , assembler(assembler)
    {
    }

    std::size_t
    n_particles() const override
    {
      return bed.particles.size();
    }

    double
    mean_radius() const override
    {
      return bed.particles.mean_radius();
    }

    double
    skin() const override
    {
      return bed.contacts.skin();
    }

    Eigen::Map<Eigen::VectorXd>
    coordinates() override
    {
      return bed.particles.coordinates();
    }

    ContactSums
    residual(Eigen::VectorXd &F) override
    {
      return assembler.residual(bed, model, F);
    }

    ContactSums
    assemble(Eigen::VectorXd &F, BlockSparseMatrix &K) override
    {
      return assembler.assemble(bed, model, F, K);
    }

    bool
    limit_closing(const Eigen::VectorXd &s,
                  Eigen::VectorXd       &factor) const override
    {
      const ParticleSystem &p = bed.particles;
      MeanOverlap           mean;
      for (const auto &c : bed.contacts.pairs)
        mean.add(p.radii[c.i] + p.radii[c.j] - branch_vector(bed, c).norm());
      const double allowance = mean.value(1e-3 * p.mean_radius());
      bool         clipped   = false;
      for (const auto &c : bed.contacts.pairs)
        {
          // Only contacts the quadratic model does not see: virgin and apart.
          if (plastic_radius(c.law, c.history) > 0.0)
            continue;
          const Eigen::Vector3d d     = branch_vector(bed, c);
          const double          dist  = d.norm();
          const double          gamma = p.radii[c.i] + p.radii[c.j] - dist;
          if (gamma > 0.0)
            continue;
          const double closing
            = -(s.segment<3>(3 * c.i) - s.segment<3>(3 * c.j)).dot(d) / dist;
          // Both particles share the closing distance.
          clipped |= limit_step_to_gap(factor, c.i, -gamma, closing, allowance);
          clipped |= limit_step_to_gap(factor, c.j, -gamma, closing, allowance);
        }
      clipped |= limit_wall_closing(bed, s, allowance, factor);
      return clipped;
    }

  private:
    BedType            &bed;
    const ContactModel &model;
    Assembler          &assembler;
  };
} // namespace compax::dem
