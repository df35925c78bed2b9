#include "dem/rve/rve_packing.h"

#include "dem/rve/deposited_packing.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace compax::dem
{
  namespace
  {
    std::string
    density_message(const double requested, const double deposit)
    {
      std::ostringstream m;
      m << "deposited packing: the relative density " << requested
        << " asked for lies below the deposit's " << deposit;
      return m.str();
    }
  } // namespace

  DepositDensityError::DepositDensityError(const double requested,
                                           const double deposit)
      : std::invalid_argument(density_message(requested, deposit))
      , requested_density(requested)
      , deposit_density(deposit)
  {
  }

  PeriodicBed
  make_rve_deposit(const PeriodicPackingSpec &spec)
  {
    DepositedPackingSpec d;
    d.particle_count = spec.particle_count;
    d.sizes          = spec.sizes;
    d.skin           = spec.skin;
    d.seed           = spec.seed;
    d.material       = spec.material;
    return make_deposited_packing(d);
  }

  PeriodicBed
  make_rve_packing(const PeriodicPackingSpec &spec,
                   const ContactModel        &model,
                   const RveLoadingOptions   &loading,
                   const unsigned int         axis,
                   const DenserDeposit        denser)
  {
    if (spec.protocol == PackingProtocol::compressed_gas)
      return make_periodic_packing(spec, model);
    if (axis > 2)
      throw std::invalid_argument("make_rve_packing: axis must be 0, 1 or 2");
    PeriodicBed bed = make_rve_deposit(spec);
    if (axis != 2)
      {
        // The deposit's direction of growth becomes the compaction axis (a
        // mirror image of the deposit: as good a packing).
        Eigen::Vector3d edges = bed.cell.lattice().diagonal();
        std::swap(edges[axis], edges[2]);
        for (Eigen::Vector3d &x : bed.particles.positions)
          std::swap(x[axis], x[2]);
        bed.cell              = PeriodicCell::box(edges, {true, true, true});
        bed.reference_lattice = bed.cell.lattice();
      }
    const double deposit = bed.relative_density();
    const double target  = spec.relative_density;
    if (target < deposit)
      {
        if (denser == DenserDeposit::reject)
          throw DepositDensityError(target, deposit);
        return bed;
      }
    // Uniaxial strain F = diag(1, 1, rho_dep / rho) along the axis, in
    // logarithmic steps of at most max_step; RveLoading cuts them further.
    const double max_step = 5e-3;
    const double strain   = std::log(target / deposit);
    const int    steps    = std::max(1, int(std::ceil(strain / max_step)));
    RveLoading   compaction(model, loading);
    for (int k = 1; k <= steps; ++k)
      {
        Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
        F(axis, axis)     = k == steps ? deposit / target
                                       : std::exp(-strain * double(k) / steps);
        if (!compaction.deform_to(bed, F).converged)
          {
            std::ostringstream m;
            m << "deposited packing: the uniaxial compaction from the "
                 "deposit's relative density "
              << deposit << " to " << target << " did not converge at "
              << bed.relative_density();
            throw std::runtime_error(m.str());
          }
      }
    bed.reference_lattice = bed.cell.lattice();
    bed.deformation       = Eigen::Matrix3d::Identity();
    return bed;
  }
} // namespace compax::dem
