#include "dem/solver/relaxation.h"

#include "dem/solver/die_bed_system.h"
#include "dem/solver/stiffness_scaling.h"

namespace compax::dem
{
  FireResult
  Relaxation::relax(Bed                &bed,
                    const ContactModel &model,
                    const double        target,
                    const int           budget,
                    const double        force_floor)
  {
    DieBedSystem system(bed, model, assembler);
    return relax(system, target, budget, force_floor);
  }

  void
  Relaxation::assemble_inverse_diagonal(EquilibriumSystem &system,
                                        Eigen::VectorXd   &F,
                                        Eigen::VectorXd   &inverse_diagonal)
  {
    sums = system.assemble(F, K);
    inverse_diagonal_stiffness(K, system.n_particles(), inverse_diagonal);
  }
} // namespace compax::dem
