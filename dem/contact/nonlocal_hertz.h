#pragma once

#include "dem/contact/contact_law.h"
#include "dem/contact/contact_law_registry.h"

#include <cmath>
#include <cstddef>
#include <vector>

/**
 * @file
 * Nonlocal contact formulation of elastic spheres (Gonzalez & Cuitino 2012):
 * the Hertz law shifted by the nonlocal overlap gamma_NL that the other
 * contact forces on both particles induce at a contact (Eqs. 5, 9, 10), and
 * two closed configurations used for verification: Tatara's two spheres
 * (Eqs. 11, 12) and the 1-D chain between rigid plates (Eq. 17). The
 * fixed-point iteration that makes forces and gamma_NL consistent over a
 * contact network (Algorithm 1), over any elastic local law, is
 * dem/nonlocal/nonlocal_contact_network.h.
 */

namespace compax::dem
{
  /**
   * Eq. (5) per unit force: the nonlocal displacement w/P [m/N] induced on a
   * contact of a sphere (radius R, Young's modulus E, Poisson's ratio nu) by
   * a unit force acting on the same sphere at angle theta from that contact,
   * theta being the angle between the two contact points seen from the
   * centre (theta = pi: opposite pole). Positive values increase the overlap
   * of the contact. A rigid body (R = E = rigid) gives 0. Valid for
   * arcsin(a/R) < theta <= pi; Eq. (5) diverges like -1/theta as theta -> 0.
   */
  double
  nonlocal_compliance(double theta, double R, double E, double nu);

  /// Eq. (5): nonlocal displacement w [m] induced by a force P [N] at angle
  /// theta on the sphere (R, E, nu).
  double
  nonlocal_displacement(double P, double theta, double R, double E, double nu);

  /// dw/dP [m/N] of Eq. (5); w is linear in P, so this is
  /// nonlocal_compliance() and does not depend on P.
  double
  nonlocal_displacement_derivative(double theta, double R, double E, double nu);

  /**
   * Nonlocal Hertz law (Gonzalez & Cuitino 2012, Eq. 10):
   * P = n_H (gamma + gamma_NL)^{3/2} for gamma + gamma_NL > 0, zero
   * otherwise, with n_H = 4/3 E sqrt(R) (Eq. 9) and gamma_NL taken from
   * ContactContext::nonlocal_overlap. The stiffness is dP/dgamma at fixed
   * gamma_NL, 3/2 n_H (gamma + gamma_NL)^{1/2}; the contact radius follows
   * from Eqs. (7)-(8): a^3 = 3 P R / (4 E) = (R (gamma + gamma_NL))^{3/2},
   * so a = sqrt(R (gamma + gamma_NL)). With gamma_NL = 0 it is HertzLaw.
   *
   * Errata and clarifications of the printed paper (used as corrected here):
   * - Eq. (4): the outer sum of the nonlocal terms is printed
   *   sum_{k=1}^{N_{P_k}}; it runs over the two particles, k = 1, 2, as in
   *   Eq. (9).
   * - Eq. (5): theta is called "the angle between the concentrated force and
   *   the z-axis"; for Eq. (11) (theta = pi for a force at the far pole,
   *   which points along +z) it must be the polar angle of the point where
   *   the force acts, measured from the contact point: the angle between the
   *   two contact directions seen from the particle's centre.
   * - Eq. (3): the text says u_z(pi) -> 0 as R -> infinity; the displacement
   *   is u_n (Appendix A, after Eq. 24) and Eq. (3) at theta = pi is
   *   (1+nu)(3-2nu) P / (4 pi R E), nonzero for finite R (it is Eq. 11).
   * - Algorithm 1, line 14 accumulates the new nonlocal terms into
   *   ^{k+1}gamma_NL without saying that they start each sweep from zero;
   *   they must (Jacobi sweep), else the sum grows with every sweep.
   *   solve_nonlocal_fixed_point() gathers the sum per contact instead of
   *   scattering it, which needs no reset and no second array.
   * - Eq. (12): the gamma^{5/2} coefficient 21/8 is that of the converged
   *   fixed point (and of the third iterate); the second iterate has 3/8 there
   *   (hidden in its O(gamma^{5/2})). The next term of the converged series is
   *   5 n_H^4 / n_NL^3 gamma^3 (derived here; the tests check it).
   */
  class NonlocalHertzLaw final : public ContactLaw
  {
  public:
    /// @param effective_radius R = (1/R1 + 1/R2)^{-1} [m]
    /// @param effective_modulus E = ((1-nu1^2)/E1 + (1-nu2^2)/E2)^{-1} [Pa]
    NonlocalHertzLaw(double effective_radius, double effective_modulus);

    /// Law of two spheres given their radii and elastic constants; pass
    /// compax::dem::rigid for the radius and modulus of a wall.
    static NonlocalHertzLaw
    for_pair(double R1,
             double E1,
             double nu1,
             double R2,
             double E2,
             double nu2);

    /// Needs the nonlocal overlap of the other contacts: the nonlocal
    /// solvers (dem/nonlocal) evaluate it, not the local particle solvers.
    static constexpr bool needs_context = true;

    /// The law's parameters and builder for the command line
    /// (contact_law_registry.h).
    static RegisteredContactLaw
    registration();

    using ContactLaw::evaluate;
    using ContactLaw::updated_history;

    ContactResponse
    evaluate(double                gamma,
             const ContactHistory &history,
             const ContactContext &context) const override;

    /// The law is elastic: the history is returned unchanged.
    ContactHistory
    updated_history(double                gamma,
                    const ContactHistory &history,
                    const ContactContext &context) const override;

    std::string
    name() const override
    {
      return "nonlocal-hertz";
    }

    /// Force, stiffness dP/dgamma (at fixed gamma_NL) and radius at overlap
    /// gamma [m] and nonlocal overlap gamma_NL [m], without virtual dispatch.
    ContactResponse
    response(double gamma, double gamma_nl) const
    {
      const double s = gamma + gamma_nl;
      if (s <= 0.0)
        return {};
      const double root = std::sqrt(s);
      return {n_H * s * root, 1.5 * n_H * root, root * sqrt_R};
    }

    /// n_H = 4/3 E sqrt(R) [N/m^{3/2}] (Eq. 9).
    double
    coefficient() const
    {
      return n_H;
    }

    double
    effective_radius() const
    {
      return R;
    }

    double
    effective_modulus() const
    {
      return E;
    }

  private:
    double R;
    double E;
    double n_H;
    double sqrt_R;
  };

  /// Radius and elastic constants of one body for the nonlocal terms. A
  /// rigid wall (radius = youngs_modulus = rigid) induces no nonlocal
  /// displacement.
  struct NonlocalBody
  {
    /// Radius R [m].
    double radius;
    /// Young's modulus E [Pa].
    double youngs_modulus;
    /// Poisson's ratio nu [-].
    double poisson_ratio;
  };

  /**
   * Lower root s of s - kappa s^{3/2} = gamma (kappa >= 0), the branch that
   * starts at s = gamma for kappa = 0; s = 0 for gamma <= 0. Newton from
   * s = gamma converges monotonically because the left side is concave.
   * Returns a negative value when there is no root, i.e. when
   * gamma > 4 / (27 kappa^2).
   */
  double
  nonlocal_scalar_root(double       gamma,
                       double       kappa,
                       double       relative_tolerance = 1e-15,
                       unsigned int max_iterations     = 100);

  /// Self-consistent solution of Tatara's configuration.
  struct TataraSolution
  {
    /// Force F at the poles = contact force [N].
    double force = 0.0;
    /// gamma_NL = F / n_NL [m] (Eq. 11).
    double nonlocal_overlap = 0.0;
    /// n_H [N/m^{3/2}] and n_NL = F / gamma_NL [N/m] of the pair.
    double n_H  = 0.0;
    double n_NL = 0.0;
    /// False when gamma exceeds the largest overlap with a solution.
    bool converged = false;
  };

  /**
   * Two spheres in contact at overlap gamma [m], loaded by forces F at their
   * far poles (theta = pi; Gonzalez & Cuitino 2012, Eq. 11, Fig. 4 left):
   * solves F = n_H (gamma + F / n_NL)^{3/2} with
   * 1/n_NL = sum_k (1+nu_k)(3-2nu_k) / (4 pi R_k E_k). Either sphere may be
   * rigid (a sphere pressed on a rigid flat by a force at its far pole).
   */
  TataraSolution
  solve_tatara_two_spheres(double gamma,
                           double R1,
                           double E1,
                           double nu1,
                           double R2,
                           double E2,
                           double nu2);

  /// Self-consistent solution of the 1-D chain between rigid plates.
  struct ChainSolution
  {
    /// Force transmitted by every contact [N].
    double force = 0.0;
    /// Overlaps of the two sphere-plate contacts and of the N-1
    /// sphere-sphere contacts [m].
    double wall_overlap   = 0.0;
    double sphere_overlap = 0.0;
    /// Their nonlocal overlaps [m].
    double wall_nonlocal_overlap   = 0.0;
    double sphere_nonlocal_overlap = 0.0;
    /// Hertz force at the same plate approach, n_H,wall (Delta / 2N)^{3/2}
    /// [N], for the discrepancy D of Eq. (16).
    double hertz_force = 0.0;
    bool   converged   = false;
  };

  /**
   * N identical spheres (R, E, nu) in a row between two rigid frictionless
   * plates whose approach is Delta [m] (Gonzalez & Cuitino 2012, Fig. 9a;
   * Tatara's experiment for N = 1). Every contact carries the same force P;
   * a sphere-plate contact sees one opposite force on its sphere
   * (gamma_NL = c P), a sphere-sphere contact one on each sphere
   * (gamma_NL = 2 c P), with c = (1+nu)(3-2nu)/(4 pi R E). Since
   * n_H,sphere = n_H,wall / 2^{3/2}, Delta = 2 gamma_w + (N-1) gamma_s gives
   * gamma_s = 2 gamma_w = Delta / N and
   * Delta / 2N = s - c n_H,wall s^{3/2} with s = (P / n_H,wall)^{2/3}.
   * The macroscopic strain of Eq. (17) is epsilon = Delta / (2 N R).
   */
  ChainSolution
  solve_chain_between_plates(unsigned int n_spheres,
                             double       plate_approach,
                             double       R,
                             double       E,
                             double       nu);
} // namespace compax::dem
