#pragma once

#include "dem/rve/periodic_packing.h"
#include "dem/rve/rve_loading.h"

#include <stdexcept>
#include <string>

namespace compax::dem
{
  /// The deposited protocol was asked for a relative density below that of
  /// its deposit (a deposit cannot be loosened).
  class DepositDensityError : public std::invalid_argument
  {
  public:
    DepositDensityError(double requested, double deposit);

    /// The relative density asked for [-].
    double requested_density;
    /// The relative density of the deposited cell [-].
    double deposit_density;
  };

  /// What make_rve_packing() does when the deposit is denser than asked.
  enum class DenserDeposit
  {
    /// Throw DepositDensityError.
    reject,
    /// Return the deposit at its own density.
    keep
  };

  /**
   * The starting packing of an RVE at spec.relative_density, by
   * spec.protocol:
   * - compressed_gas: make_periodic_packing(spec, model) (virgin);
   * - deposited: make_deposited_packing() with the spec's count, sizes,
   *   skin, seed and material (virgin, touching, at the deposit's density
   *   rho_dep; mirrored so that its direction of growth z becomes `axis`),
   *   then, if spec.relative_density is higher, compacted by
   *   uniaxial strain along `axis` (the deposit's direction of growth, a
   *   die's compaction axis) with RveLoading and `loading` (by default the
   *   bonded path: the histories grow where the contact forces are
   *   resolved) in logarithmic steps of at most 5e-3, to exactly that
   *   density. The compacted cell is the new reference (deformation I,
   *   reference lattice its lattice). A lower spec.relative_density is
   *   rejected or ignored as `denser` says.
   * Deterministic: the same arguments give the same cell.
   */
  PeriodicBed
  make_rve_packing(const PeriodicPackingSpec &spec,
                   const ContactModel        &model,
                   const RveLoadingOptions   &loading = {},
                   unsigned int               axis    = 2,
                   DenserDeposit              denser  = DenserDeposit::reject);

  /// The deposited cell of make_rve_packing() before compaction (virgin).
  PeriodicBed
  make_rve_deposit(const PeriodicPackingSpec &spec);
} // namespace compax::dem
