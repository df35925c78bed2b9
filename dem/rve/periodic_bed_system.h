#pragma once

#include "dem/rve/periodic_assembler.h"
#include "dem/solver/equilibrium_system.h"

namespace compax::dem
{
  /**
   * A periodic cell as an EquilibriumSystem, so that the die's trust-region
   * Newton and FIRE solve for the fluctuations at a fixed lattice. Rigid
   * translations are a null space of K; the residual is orthogonal to it,
   * which the Steihaug-Toint solves respect.
   */
  class PeriodicBedSystem final : public EquilibriumSystem
  {
  public:
    PeriodicBedSystem(PeriodicBed        &bed,
                      const ContactModel &model,
                      PeriodicAssembler  &assembler)
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
    PeriodicBed        &bed;
    const ContactModel &model;
    PeriodicAssembler  &assembler;
  };
} // namespace compax::dem
