#include "dem/die/die_analysis.h"

#include <algorithm>

namespace compax::dem
{
  BedMeasures
  measure(const Bed &bed)
  {
    BedMeasures m;
    std::size_t loaded = 0;
    double      ap2 = 0.0, r2 = 0.0;
    const auto &p = bed.particles;
    for (const PairContact &c : bed.contacts.pairs)
      {
        const double P
          = c.law.response(pair_overlap(p, c), c.history.a_p, c.history.a_B)
              .force;
        if (P != 0.0)
          ++loaded;
        m.n_tensile += P < 0.0;
        m.n_compressive += P > 0.0;
        m.n_bonds += c.history.a_B > 0.0;
        ap2 += c.history.a_p * c.history.a_p;
      }
    for (const double R : p.radii)
      r2 += R * R;
    if (p.size() > 0)
      {
        m.coordination_number = 2.0 * loaded / p.size();
        m.bonding_surface     = ap2 / r2;
      }
    return m;
  }

  std::vector<double>
  pair_forces(const Bed &bed)
  {
    std::vector<double> f;
    for (const PairContact &c : bed.contacts.pairs)
      {
        const double P = c.law
                           .response(pair_overlap(bed.particles, c),
                                     c.history.a_p,
                                     c.history.a_B)
                           .force;
        if (P != 0.0)
          f.push_back(P);
      }
    return f;
  }

  namespace
  {
    double
    slope(const std::vector<double> &x, const std::vector<double> &y)
    {
      const double n  = x.size();
      double       sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          sx += x[i];
          sy += y[i];
          sxx += x[i] * x[i];
          sxy += x[i] * y[i];
        }
      const double d = n * sxx - sx * sx;
      return d != 0.0 ? (n * sxy - sx * sy) / d : 0.0;
    }
  } // namespace

  TabletElasticity
  unloading_elasticity(const std::vector<double> &strain,
                       const std::vector<double> &axial,
                       const std::vector<double> &radial)
  {
    TabletElasticity t;
    if (axial.empty())
      return t;
    const double        s_max = *std::max_element(axial.begin(), axial.end());
    std::vector<double> e, sz, sr;
    for (std::size_t i = 0; i < axial.size(); ++i)
      if (axial[i] >= s_max / 3.0 && axial[i] <= 2.0 * s_max / 3.0)
        {
          e.push_back(strain[i]);
          sz.push_back(axial[i]);
          sr.push_back(radial[i]);
        }
    t.n_points = static_cast<int>(e.size());
    if (e.size() < 2)
      return t;
    const double M   = -slope(e, sz); // stress drops as the strain grows
    const double k   = slope(sz, sr);
    t.poisson_ratio  = k / (1.0 + k);
    const double nu  = t.poisson_ratio;
    t.youngs_modulus = M * (1.0 + nu) * (1.0 - 2.0 * nu) / (1.0 - nu);
    return t;
  }
} // namespace compax::dem
