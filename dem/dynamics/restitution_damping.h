#pragma once

namespace compax::dem
{
  /**
   * Viscous damping of a Hertzian contact set from a coefficient of
   * restitution.
   *
   * The dashpot is the one of the Hertz-Mindlin model of Eq. (2) of
   * Giannis 2021 in the common (Tsuji-type) form
   *   F_d = 2 zeta sqrt(m* S_n) d(delta)/dt,  S_n = 2 E* sqrt(R* delta),
   * i.e. proportional to delta^{1/4}. With the elastic force
   * k delta^{3/2}, k = 4/3 E* sqrt(R*), the collision scales to
   *   u'' = -u^{3/2} - 2 sqrt(3/2) zeta u^{1/4} u',  u(0) = 0, u'(0) = 1,
   * whatever the masses, radii, moduli and impact speed, so the
   * coefficient of restitution e = -u'(t_end) depends on zeta alone. The
   * frequently used closed form zeta = -sqrt(5/6) ln e /
   * sqrt(ln^2 e + pi^2) (EDEM's Hertz-Mindlin) transfers the linear-spring
   * result and misses e by a few per cent; here e(zeta) is integrated (RK4,
   * 4000 steps per contact) and inverted by bisection, so a binary collision
   * reproduces e to the integration accuracy of the DEM step.
   */
  double
  hertz_restitution(double damping_ratio);

  /// zeta >= 0 with hertz_restitution(zeta) = e, for e in (0, 1].
  double
  hertz_damping_ratio(double restitution);
} // namespace compax::dem
