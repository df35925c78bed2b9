#pragma once

#include "dem/solver/bed.h"
#include "dem/solver/contact_assembler.h"
#include "dem/solver/equilibrium_system.h"

#include <algorithm>

namespace compax::dem
{
  /**
   * A bed in a die as an EquilibriumSystem: the particles between the
   * punches and the die wall, with the contact law of a ContactModel.
   * Holds references only; the assembler keeps the stiffness pattern
   * between calls.
   */
  class DieBedSystem final : public EquilibriumSystem
  {
  public:
    DieBedSystem(Bed                &bed,
                 const ContactModel &model,
                 ContactAssembler   &assembler)
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
                  Eigen::VectorXd       &factor) const override;

  private:
    Bed                &bed;
    const ContactModel &model;
    ContactAssembler   &assembler;
  };

  /// Mean of the positive overlaps (contacts in compression) [m], or
  /// `fallback` if none: the overlap a closing contact may reach within one
  /// solver step (the force scale the quadratic model already knows).
  class MeanOverlap
  {
  public:
    void
    add(const double gamma)
    {
      if (gamma > 0.0)
        {
          sum += gamma;
          ++n;
        }
    }

    double
    value(const double fallback) const
    {
      return n > 0 ? sum / n : fallback;
    }

  private:
    double      sum = 0.0;
    std::size_t n   = 0;
  };

  /// factor[i] = min(factor[i], (gap + allowance) / closing) when the
  /// particle's step closes a gap by more than gap + allowance; returns
  /// whether it did.
  inline bool
  limit_step_to_gap(Eigen::VectorXd  &factor,
                    const std::size_t i,
                    const double      gap,
                    const double      closing,
                    const double      allowance)
  {
    if (closing <= gap + allowance)
      return false;
    factor[i] = std::min(factor[i], (gap + allowance) / closing);
    return true;
  }
} // namespace compax::dem
