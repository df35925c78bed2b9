#pragma once

#include "coupling/rve_database.h"
#include "fem/material_model.h"

#include <string>
#include <vector>

namespace compax::coupling
{
  /**
   * A continuum law driven along the paths of an RVE database: the rows
   * form a tree (DatabaseRow::parent); each row's state is the law's state
   * at its parent advanced by the increment of the cell's deformation,
   * F_inc = F_row F_parent^-1 (symmetric on every database path), given to
   * the law as the logarithmic strain increment ln(F_inc) with F_inc as
   * its deformation increment (so the law's mass balance gives the cell's
   * density exactly). The first row is the law's unstressed state at the
   * packing's density. An increment the law cannot return is split into
   * 2, 4, ... equal logarithmic sub-increments (up to 64).
   *
   * Returns the law's Cauchy stress (Voigt, tension positive) per row.
   * Throws std::runtime_error if an increment fails even when split.
   */
  std::vector<dem::Vector6d>
  drive_along_database(const RveDatabase        &database,
                       const fem::MaterialModel &law);

  /// Difference between two responses along one path of a database.
  struct PathError
  {
    int         branch; ///< -1: compaction
    std::string path;
    bool        training; ///< is_training_path(path)
    /// Relative density at the first row of the path [-].
    double      relative_density;
    std::size_t points;
    /// sqrt(sum |sigma - sigma_ref|^2 / sum |sigma_ref|^2) over the path's
    /// rows (Frobenius norms) [-]: the stress error relative to the RMS
    /// stress of the reference along the path.
    double stress_error;
    /// sqrt(sum (p - p_ref)^2 / sum (p_ref^2 + q_ref^2)) [-] and the same
    /// for q: the errors in pressure and in von Mises stress, relative to
    /// the same RMS stress measure.
    double p_error;
    double q_error;
  };

  /**
   * Path-by-path relative differences between a response `other` and a
   * reference `reference`. Paths are matched by (branch, path name); the
   * k-th row of a path in one is compared with the k-th row in the other,
   * over the rows both have (an unloading path may end a step earlier in
   * one of two different packings). Paths missing in `other` are skipped.
   */
  std::vector<PathError>
  path_errors(const RveDatabase &reference, const RveDatabase &other);

  /// `database` with every row's stress replaced by `stress` (e.g. the
  /// response of drive_along_database()).
  RveDatabase
  with_stresses(RveDatabase database, const std::vector<dem::Vector6d> &stress);

  /// Pooled error over the paths whose training flag is `training`:
  /// sqrt(sum over their rows of |d sigma|^2 / sum |sigma_ref|^2), weighted
  /// as the per-path errors are; NaN if there is none.
  double
  pooled_stress_error(const RveDatabase &reference,
                      const RveDatabase &other,
                      bool               training);
} // namespace compax::coupling
