#pragma once

#include "dem/rve/periodic_bed.h"
#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_path_study.h"
#include "dem/solver/contact_model.h"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace compax::dem
{
  /// What an RVE-size study does: one path study per cell size.
  struct RveSizeStudyOptions
  {
    /// The packing of every cell; cell k has cell_sizes[k] particles and
    /// the seed packing.seed + k.
    PeriodicPackingSpec      packing;
    std::vector<std::size_t> cell_sizes;
    /// The path of every cell.
    RvePathStudyOptions path;
  };

  /// The quantities compared between cell sizes: at the end of loading
  /// (stress, and moduli of the last tangent of loading) and at the end of
  /// the path (moduli of the last tangent).
  const std::vector<std::string> &
  rve_size_quantities();

  /// One cell of a size study.
  struct RveSizeCell
  {
    PeriodicPackingSpec packing;
    /// Cell edge over mean particle diameter (cube root of the volume) [-].
    double        edge_over_diameter = 0.0;
    RvePathResult path;
    /// rve_size_quantities() of this cell, NaN where not reached.
    std::vector<double> quantities;
  };

  /// The spread of one quantity between the cell sizes.
  struct RveSizeSpread
  {
    std::string quantity;
    /// Cells with a value (NaN otherwise).
    int    count = 0;
    double min   = 0.0;
    double max   = 0.0;
    double mean  = 0.0;
    /// (max - min) / |mean| (NaN for a zero mean).
    double spread = 0.0;
  };

  /// What a size study computed: per cell its path and quantities, per
  /// quantity the spread between the cells.
  struct RveSizeResult
  {
    /// The cells run, in order; a cell whose path failed is the last.
    std::vector<RveSizeCell>   cells;
    std::vector<RveSizeSpread> spread;
    bool                       converged = true;
  };

  /// Progress reports of a size study (each may be empty).
  struct RveSizeObserver
  {
    /// Before cell k is packed.
    std::function<void(std::size_t k, const PeriodicPackingSpec &)> packing;
    /// Cell k packed.
    std::function<void(std::size_t k, const PeriodicBed &)> packed;
    /// The observer of cell k's path.
    std::function<RvePathObserver(std::size_t k)> path;
    /// Cell k's path done; `study` holds its final state.
    std::function<
      void(std::size_t k, const RveSizeCell &, const RvePathStudy &)>
      done;
  };

  /**
   * RVE-size study (Giannis 2021 Sec. 4.1): the same path for every cell
   * size, per size the stress at the end of loading and the moduli there
   * and at the end, and the spread (max - min)/|mean| between the sizes,
   * the measure of whether a cell is representative.
   */
  class RveSizeStudy
  {
  public:
    RveSizeStudy(ContactModel model, RveSizeStudyOptions options);

    /// The packing of cell k.
    PeriodicPackingSpec
    packing(std::size_t k) const;

    /// Packs and runs every cell; stops after a cell whose path failed.
    /// A DepositDensityError of a packing passes through.
    RveSizeResult
    run(const RveSizeObserver &observer = {}) const;

  private:
    ContactModel        model;
    RveSizeStudyOptions options;
  };

  /// The spread of one quantity over values (NaN entries left out).
  RveSizeSpread
  size_spread(const std::string &quantity, const std::vector<double> &values);
} // namespace compax::dem
