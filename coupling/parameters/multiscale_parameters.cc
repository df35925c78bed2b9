#include "coupling/parameters/multiscale_parameters.h"

#include "coupling/parameters/database_parameters.h"
#include "input/parameter_declaration.h"
#include "input/real_interval.h"

namespace compax::coupling
{
  fem::MaterialRegistry
  tablet_materials()
  {
    fem::MaterialRegistry materials = fem::closed_form_materials();
    materials.add({"multiscale-database",
                   "an RVE response database is built first (subsection "
                   "Multiscale) and the Drucker-Prager Cap fitted to it "
                   "drives the tablet",
                   {},
                   {}});
    materials.add({"multiscale-fe2",
                   "an RVE per quadrature point (subsection Multiscale; "
                   "experimental: with small cells it does not yet get past "
                   "the jamming transition)",
                   {},
                   {}});
    return materials;
  }

  void
  declare_multiscale_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Multiscale");
    declare_database_parameters(prm);
    prm.declare_entry("Pool size",
                      "4",
                      dealii::Patterns::Integer(1, 1000),
                      "multiscale-fe2: distinct RVE packings; the quadrature "
                      "points of cell n start from copies of packing n mod "
                      "pool size "
                      "(start-up costs this many packings), in [1, 1000]. "
                      "Unit: -.");
    input::declare_quantity(
      prm,
      "Tangent floor modulus",
      "1e6",
      input::non_negative(),
      "Pa",
      "multiscale-fe2: Young's modulus of a weak isotropic "
      "hypoelastic skeleton (Poisson's ratio 0.25) in "
      "parallel with each RVE, so that points whose powder "
      "has no contact network yet keep the continuum Newton "
      "well-posed; what it adds to the stress is set by "
      "Tangent floor stress.");
    prm.declare_entry(
      "Tangent floor stress",
      "released-at-jamming",
      dealii::Patterns::Selection("released-at-jamming|accumulated"),
      "multiscale-fe2: released-at-jamming (default): the floor's stress is "
      "integrated while a point is loose and released when the point "
      "switches to its jammed packing (whose stress, the jamming pressure, "
      "already is that of the powder consolidated to it); from then on the "
      "floor only adds its stiffness to the tangent (a modified Newton "
      "whose error is multiplied by at most Ef / (Ef + E_RVE) per iteration), "
      "so "
      "none of its compaction stress remains in the ejected tablet. "
      "accumulated: the "
      "former scheme, the floor's stress integrated over the whole cycle "
      "and added to the RVE's (Ef x the summed strain increments, a mean "
      "stress of -0.4 MPa after uniaxial compaction from 0.5 to 0.9 at "
      "1 MPa, stays in the ejected tablet, balanced by tension in its "
      "RVEs). Unit: -.");
    prm.declare_entry("FE2 stress resolution",
                      "1e-3",
                      dealii::Patterns::Double(0.0, 0.1),
                      "multiscale-fe2: relative accuracy of the homogenized "
                      "stress; the continuum Newton tolerance is raised to "
                      "it, in [0, 0.1]. An RVE's stress is piecewise smooth: "
                      "contact events change it by ~1e-4 of its magnitude "
                      "between neighbouring trial strains, below which "
                      "Newton cannot balance it. Unit: -.");
    prm.leave_subsection();
  }

  void
  check_multiscale_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Multiscale");
    get_database_setup(prm, "Multiscale/");
    prm.leave_subsection();
  }

} // namespace compax::coupling
