#pragma once

#include "dem/rve/periodic_bed.h"

#include <Eigen/Core>

namespace compax::dem
{
  /**
   * The steps every driver of a periodic cell (RveLoading,
   * NonlocalRveLoading) offers in terms of its own two:
   * `deform_to(bed, F)`, which deforms the cell to H = F H_0 in sub-steps,
   * and `substep(bed, F, total)`, one sub-step to F that returns whether it
   * converged and adds its counts to `total` (a `Result`). `Loading`
   * derives from CellSteps<Loading, Result> and befriends it.
   */
  template <typename Loading, typename Result>
  class CellSteps
  {
  public:
    /// Applies a small strain increment to the current configuration:
    /// F <- (I + eps) F, eps symmetric.
    Result
    apply_strain(PeriodicBed &bed, const Eigen::Matrix3d &strain_increment)
    {
      return loading().deform_to(
        bed,
        (Eigen::Matrix3d::Identity() + strain_increment) * bed.deformation);
    }

    /// Equilibrium at the current cell without moving it, as one sub-step
    /// (with the history update where the law has one), e.g. after a
    /// restart or a change of material.
    Result
    equilibrate(PeriodicBed &bed)
    {
      Result total;
      total.converged = loading().substep(bed, bed.deformation, total);
      total.substeps  = total.converged ? 1 : 0;
      return total;
    }

  private:
    Loading &
    loading()
    {
      return static_cast<Loading &>(*this);
    }
  };
} // namespace compax::dem
