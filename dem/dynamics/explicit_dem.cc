#include "dem/dynamics/explicit_dem.h"

#include "dem/contact/pair_properties.h"
#include "dem/dynamics/restitution_damping.h"
#include "dem/numbers.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// What the contact resolution needs to know about one contact.
    struct ContactInput
    {
      Eigen::Vector3d n;       ///< unit normal from i to j
      double          delta;   ///< overlap > 0
      double          lever_i; ///< centre of i to contact point
      double          lever_j; ///< centre of j to contact point
      Eigen::Vector3d v_rel;   ///< velocity of j's surface minus i's
      Eigen::Vector3d w_rel;   ///< omega_i - omega_j
      double          R;       ///< effective radius
      double          E;       ///< effective modulus
      double          G;       ///< effective shear modulus
      double          m;       ///< effective mass
      double          I;       ///< effective moment of inertia
      double          P;       ///< particle pressure P_ij (tension +)
      double          zeta;    ///< dashpot damping ratio
      double          mu;      ///< sliding friction
      double          mu_r;    ///< rolling friction
    };

    struct ContactOutput
    {
      Eigen::Vector3d force_on_j;
      Eigen::Vector3d torque_i;
      Eigen::Vector3d torque_j;
      double          normal_force; ///< law force without dashpot
      double          stiffness;    ///< |k_n| + 3.5 k_t for the time step
    };

    /// The normal law's part of a contact at one evaluation.
    struct NormalResponse
    {
      /// Force of the law, positive repulsive [N].
      double force;
      /// Stiffness that sets the dashpot, 2 zeta sqrt(m k) [N/m].
      double dashpot_stiffness;
      /// Stiffness that bounds the time step [N/m].
      double step_stiffness;
    };

    /// The multi-contact law (Eqs. 6-14); delta_max follows the overlap.
    inline NormalResponse
    multicontact_response(const ContactInput                        &c,
                          const MulticontactAdhesiveLaw::Parameters &law,
                          ContactHistory                            &history)
    {
      const MulticontactAdhesiveLaw contact_law(c.R, c.E, law);
      const ContactResponse         r
        = contact_law.response(c.delta,
                               MulticontactAdhesiveLaw::delta_max(history),
                               c.P);
      history = MulticontactAdhesiveLaw::with_largest_overlap(history, c.delta);
      return {r.force,
              2.0 * c.E * std::sqrt(c.R * c.delta),
              std::abs(r.stiffness)};
    }

    /**
     * A particle law: force at the current history, then the history of
     * this state (updated_history). The step is bounded by the stiffer of
     * the current branch and the one the contact would unload along.
     */
    inline NormalResponse
    particle_law_response(const ParticleLaw &law,
                          const double       delta,
                          ContactHistory    &history)
    {
      const ContactResponse r = law_response(law, delta, history);
      const double unloading  = unloading_stiffness(law, delta, history);
      history                 = updated_history(law, delta, history);
      const double k          = std::abs(r.stiffness);
      return {r.force, k, std::max(k, std::abs(unloading))};
    }

    /// Dashpot, Coulomb-limited Mindlin spring (none at a non-positive
    /// overlap, where a bonded contact pulls), rolling torque around the
    /// normal force @p normal. Updates the tangential spring xi.
    inline ContactOutput
    resolve(const ContactInput   &c,
            const NormalResponse &normal,
            const bool            friction,
            const double          dt,
            Eigen::Vector3d      &xi)
    {
      const double root = std::sqrt(c.R * std::max(c.delta, 0.0));
      const double S_t  = 8.0 * c.G * root;
      const double v_n  = c.v_rel.dot(c.n); // > 0 separating
      const double F_n
        = normal.force
          - 2.0 * c.zeta * std::sqrt(c.m * normal.dashpot_stiffness) * v_n;

      ContactOutput out;
      out.normal_force = normal.force;
      out.stiffness    = normal.step_stiffness;
      out.force_on_j   = F_n * c.n;
      out.torque_i.setZero();
      out.torque_j.setZero();
      if (!friction || (c.mu <= 0.0 && c.mu_r <= 0.0) || c.delta <= 0.0)
        {
          xi.setZero();
          return out;
        }

      // Tangential spring, rotated into the current tangent plane.
      const Eigen::Vector3d v_t = c.v_rel - v_n * c.n;
      const double          old = xi.norm();
      xi -= xi.dot(c.n) * c.n;
      const double now = xi.norm();
      if (now > 0.0)
        xi *= old / now;
      xi += v_t * dt;
      const double    gamma_t = 2.0 * c.zeta * std::sqrt(c.m * S_t);
      Eigen::Vector3d F_t     = -S_t * xi - gamma_t * v_t;
      const double    limit   = c.mu * std::max(normal.force, 0.0);
      const double    F_t_abs = F_t.norm();
      if (F_t_abs > limit)
        {
          F_t *= F_t_abs > 0.0 ? limit / F_t_abs : 0.0;
          xi = S_t > 0.0 ? Eigen::Vector3d(-(F_t + gamma_t * v_t) / S_t)
                         : Eigen::Vector3d::Zero();
        }
      out.force_on_j += F_t;
      out.stiffness += 3.5 * S_t;
      // Torques of the tangential force about the centres.
      out.torque_i = (c.lever_i * c.n).cross(-F_t);
      out.torque_j = (-c.lever_j * c.n).cross(F_t);

      // Constant directional torque (Eq. 5), R_r = R*.
      const double w = c.w_rel.norm();
      if (c.mu_r > 0.0 && w > 0.0)
        {
          const double T = std::min(c.mu_r * c.R * std::max(normal.force, 0.0),
                                    dt > 0.0 ? w * c.I / dt : 0.0);
          const Eigen::Vector3d torque = (T / w) * c.w_rel;
          out.torque_i -= torque;
          out.torque_j += torque;
        }
      return out;
    }

    /// Recoverable normal energy along the current un/reloading branch.
    double
    normal_energy(const MulticontactAdhesiveLaw &law,
                  const double                   delta,
                  const double                   delta_max)
    {
      if (delta <= 0.0)
        return 0.0;
      const double dm  = std::max(delta, delta_max);
      const double k2s = law.unloading_stiffness(dm);
      const double x0
        = (1.0 - law.loading_stiffness() / k2s) * dm * std::sqrt(dm);
      const double d0 = std::cbrt(x0 * x0);
      return k2s
             * (0.4
                  * (delta * delta * std::sqrt(delta) - d0 * d0 * std::sqrt(d0))
                - x0 * (delta - d0));
    }
  } // namespace

  ExplicitDem::ExplicitDem(const DemMaterial      &material,
                           const PeriodicCell     &cell,
                           const DynamicsSettings &settings)
      : mat(material)
      , periodic_cell(cell)
      , settings(settings)
  {
    mat.normal_law.poisson_ratio = mat.poisson_ratio;
    const double G = shear_modulus(mat.youngs_modulus, mat.poisson_ratio);
    const double Gw
      = shear_modulus(mat.wall_youngs_modulus, mat.wall_poisson_ratio);
    E_pp = effective_modulus(mat.youngs_modulus,
                             mat.poisson_ratio,
                             mat.youngs_modulus,
                             mat.poisson_ratio);
    G_pp = effective_shear_modulus(G, mat.poisson_ratio, G, mat.poisson_ratio);
    E_pw = effective_modulus(mat.youngs_modulus,
                             mat.poisson_ratio,
                             mat.wall_youngs_modulus,
                             mat.wall_poisson_ratio);
    G_pw = effective_shear_modulus(G,
                                   mat.poisson_ratio,
                                   Gw,
                                   mat.wall_poisson_ratio);
    zeta_pp = hertz_damping_ratio(mat.particle_particle.restitution);
    zeta_pw = hertz_damping_ratio(mat.particle_wall.restitution);
    if (!(settings.mass_scaling > 0.0))
      throw std::invalid_argument("mass scaling must be positive");
  }

  std::size_t
  ExplicitDem::add_particle(const Eigen::Vector3d &position,
                            const double           radius)
  {
    p.position.push_back(position);
    p.velocity.push_back(Eigen::Vector3d::Zero());
    p.angular_velocity.push_back(Eigen::Vector3d::Zero());
    p.force.push_back(Eigen::Vector3d::Zero());
    p.torque.push_back(Eigen::Vector3d::Zero());
    p.radius.push_back(0.0);
    p.mass.push_back(0.0);
    p.inverse_mass.push_back(0.0);
    p.inverse_inertia.push_back(0.0);
    p.stress.push_back(Eigen::Matrix3d::Zero());
    p.pressure.push_back(0.0);
    p.kinematic.push_back(0);
    if (model)
      wall_laws.push_back(model->wall_law(0, radius));
    walls.resize(2 * p.size());
    stiffness_sum.resize(p.size());
    set_radius(p.size() - 1, radius);
    list_valid   = false;
    forces_valid = false;
    return p.size() - 1;
  }

  void
  ExplicitDem::set_radius(const std::size_t i, const double radius)
  {
    if (!(radius > 0.0))
      throw std::invalid_argument("particle radius must be positive");
    const double m = settings.mass_scaling * mat.density * 4.0 / 3.0 * pi
                     * radius * radius * radius;
    p.radius[i]          = radius;
    p.mass[i]            = m;
    p.inverse_mass[i]    = 1.0 / m;
    p.inverse_inertia[i] = 1.0 / (0.4 * m * radius * radius);
    if (model)
      {
        // The laws change with the radius: every pair law is built anew
        // at the next neighbour update.
        wall_laws[i] = model->wall_law(0, radius);
        laws_stale   = true;
        list_valid   = false;
      }
  }

  void
  ExplicitDem::set_kinematic(const std::size_t i, const bool kinematic)
  {
    p.kinematic[i] = kinematic ? 1 : 0;
  }

  void
  ExplicitDem::add_plates(const double bottom, const double top)
  {
    if (!(top > bottom))
      throw std::invalid_argument("top plate must be above the bottom plate");
    plates[0].position = bottom;
    plates[1].position = top;
    plates_enabled     = true;
    forces_valid       = false;
  }

  void
  ExplicitDem::set_normal_law(const MulticontactAdhesiveLaw::Parameters &law)
  {
    // Validates the parameters once, here, rather than in the force loop.
    MulticontactAdhesiveLaw(1.0, 1.0, law);
    mat.normal_law               = law;
    mat.normal_law.poisson_ratio = mat.poisson_ratio;
  }

  void
  ExplicitDem::use_contact_model(const ContactModel &contact_model)
  {
    model.emplace(contact_model);
    wall_laws.clear();
    for (const double r : p.radius)
      wall_laws.push_back(model->wall_law(0, r));
    pairs.clear();
    reset_contact_history();
    list_valid   = false;
    forces_valid = false;
  }

  void
  ExplicitDem::reset_contact_history()
  {
    for (auto &c : pairs)
      {
        c.history = ContactHistory{};
        c.tangential.setZero();
      }
    for (auto &w : walls)
      {
        w.history = ContactHistory{};
        w.tangential.setZero();
      }
  }

  double
  ExplicitDem::rayleigh_limit() const
  {
    double r_min = std::numeric_limits<double>::infinity();
    for (const double r : p.radius)
      r_min = std::min(r_min, r);
    return settings.rayleigh_factor
           * rayleigh_time_step(r_min,
                                settings.mass_scaling * mat.density,
                                mat.youngs_modulus,
                                mat.poisson_ratio);
  }

  double
  ExplicitDem::time_step()
  {
    if (!forces_valid)
      {
        update_neighbours(false);
        compute_forces(0.0);
        forces_valid = true;
      }
    return dt;
  }

  void
  ExplicitDem::update_neighbours(const bool force)
  {
    const std::size_t n       = p.size();
    bool              rebuild = force || !list_valid;
    if (!rebuild)
      {
        double move2 = 0.0, grow = 0.0;
        for (std::size_t i = 0; i < n; ++i)
          {
            move2
              = std::max(move2,
                         (p.position[i] - position_at_build[i]).squaredNorm());
            grow = std::max(grow, p.radius[i] - radius_at_build[i]);
          }
        rebuild = 2.0 * (std::sqrt(move2) + grow) >= skin_at_build;
      }
    if (!rebuild)
      return;

    double r_min = std::numeric_limits<double>::infinity();
    for (const double r : p.radius)
      r_min = std::min(r_min, r);
    skin_at_build = settings.skin > 0.0 ? settings.skin : 0.25 * r_min;
    grid.find_pairs(
      periodic_cell, p.position, p.radius, skin_at_build, candidates);

    // Carry the histories (and laws) over: both lists are sorted by
    // (i, j, image).
    next_pairs.resize(candidates.size());
    next_pair_laws.clear();
    std::size_t old = 0;
    for (std::size_t k = 0; k < candidates.size(); ++k)
      {
        const ImagePair    &c = candidates[k];
        DynamicPairContact &s = next_pairs[k];
        s.i                   = c.i;
        s.j                   = c.j;
        s.image               = c.image;
        s.offset              = periodic_cell.image_offset(c.image);
        s.history             = ContactHistory{};
        s.tangential.setZero();
        s.overlap      = 0.0;
        s.normal_force = 0.0;
        while (old < pairs.size()
               && ImagePair{pairs[old].i, pairs[old].j, pairs[old].image} < c)
          ++old;
        const bool kept = old < pairs.size() && pairs[old].i == c.i
                          && pairs[old].j == c.j && pairs[old].image == c.image;
        if (kept)
          {
            s.history      = pairs[old].history;
            s.tangential   = pairs[old].tangential;
            s.overlap      = pairs[old].overlap;
            s.normal_force = pairs[old].normal_force;
          }
        if (model)
          next_pair_laws.push_back(
            kept && !laws_stale && old < pair_laws.size()
              ? pair_laws[old]
              : model->pair_law(0, p.radius[c.i], 0, p.radius[c.j]));
      }
    pairs.swap(next_pairs);
    pair_laws.swap(next_pair_laws);
    laws_stale        = false;
    position_at_build = p.position;
    radius_at_build   = p.radius;
    list_valid        = true;
    ++rebuild_count;
  }

  void
  ExplicitDem::compute_forces(const double h)
  {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i)
      {
        p.force[i] = mat.gravity * p.mass[i];
        p.torque[i].setZero();
        p.stress[i].setZero();
        stiffness_sum[i] = 0.0;
      }
    plates[0].force.setZero();
    plates[1].force.setZero();
    const auto &law = mat.normal_law;
    // A contact apart acts only if its law keeps internal variables there
    // (a bonded bridge); the multi-contact law forgets them.
    const auto acts_apart = [&](const ContactHistory &history) {
      return model && !(history == ContactHistory{});
    };

    // Particle-particle contacts.
    for (std::size_t k = 0; k < pairs.size(); ++k)
      {
        DynamicPairContact   &c = pairs[k];
        const std::uint32_t   i = c.i, j = c.j;
        const Eigen::Vector3d d  = p.position[j] - p.position[i] + c.offset;
        const double          Rs = p.radius[i] + p.radius[j];
        const double          d2 = d.squaredNorm();
        if (d2 >= Rs * Rs && !acts_apart(c.history))
          {
            // Contact lost (or not yet made): no history.
            c.overlap      = Rs - std::sqrt(d2);
            c.normal_force = 0.0;
            c.history      = ContactHistory{};
            c.tangential.setZero();
            continue;
          }
        const double dist = std::sqrt(d2);
        ContactInput in;
        in.n       = d / dist;
        in.delta   = Rs - dist;
        in.lever_i = p.radius[i] - 0.5 * in.delta;
        in.lever_j = p.radius[j] - 0.5 * in.delta;
        in.v_rel
          = p.velocity[j] + p.angular_velocity[j].cross(-in.lever_j * in.n)
            - p.velocity[i] - p.angular_velocity[i].cross(in.lever_i * in.n);
        in.w_rel = p.angular_velocity[i] - p.angular_velocity[j];
        in.R     = p.radius[i] * p.radius[j] / Rs;
        in.E     = E_pp;
        in.G     = G_pp;
        in.m     = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
        in.I     = 1.0 / (p.inverse_inertia[i] + p.inverse_inertia[j]);
        in.P     = p.pressure[i] + p.pressure[j];
        in.zeta  = zeta_pp;
        in.mu    = mat.particle_particle.sliding_friction;
        in.mu_r  = mat.particle_particle.rolling_friction;

        const NormalResponse normal
          = model ? particle_law_response(pair_laws[k], in.delta, c.history)
                  : multicontact_response(in, law, c.history);
        const ContactOutput out
          = resolve(in, normal, friction, h, c.tangential);
        c.overlap      = in.delta;
        c.normal_force = out.normal_force;

        p.force[j] += out.force_on_j;
        p.force[i] -= out.force_on_j;
        p.torque[i] += out.torque_i;
        p.torque[j] += out.torque_j;
        const Eigen::Matrix3d fn = out.force_on_j * in.n.transpose();
        p.stress[i].noalias() -= in.lever_i * fn;
        p.stress[j].noalias() -= in.lever_j * fn;
        stiffness_sum[i] += out.stiffness;
        stiffness_sum[j] += out.stiffness;
      }

    // Particle-plate contacts: the plate is partner j.
    if (plates_enabled)
      for (std::size_t i = 0; i < n; ++i)
        for (int w = 0; w < 2; ++w)
          {
            PlateContact &c     = walls[2 * i + w];
            const double  gap   = w == 0 ? p.position[i][2] - plates[0].position
                                         : plates[1].position - p.position[i][2];
            const double  delta = p.radius[i] - gap;
            if (delta <= 0.0 && !acts_apart(c.history))
              {
                c.overlap      = delta;
                c.normal_force = 0.0;
                c.history      = ContactHistory{};
                c.tangential.setZero();
                continue;
              }
            ContactInput in;
            in.n       = Eigen::Vector3d(0.0, 0.0, w == 0 ? -1.0 : 1.0);
            in.delta   = delta;
            in.lever_i = gap;
            in.lever_j = 0.0;
            in.v_rel   = Eigen::Vector3d(0.0, 0.0, plates[w].velocity)
                       - p.velocity[i]
                       - p.angular_velocity[i].cross(in.lever_i * in.n);
            in.w_rel = p.angular_velocity[i];
            in.R     = p.radius[i];
            in.E     = E_pw;
            in.G     = G_pw;
            in.m     = p.mass[i];
            in.I     = 1.0 / p.inverse_inertia[i];
            in.P     = p.pressure[i];
            in.zeta  = zeta_pw;
            in.mu    = mat.particle_wall.sliding_friction;
            in.mu_r  = mat.particle_wall.rolling_friction;
            const NormalResponse normal
              = model ? particle_law_response(wall_laws[i], delta, c.history)
                      : multicontact_response(in, law, c.history);
            const ContactOutput out
              = resolve(in, normal, friction, h, c.tangential);
            c.overlap      = delta;
            c.normal_force = out.normal_force;
            plates[w].force += out.force_on_j;
            p.force[i] -= out.force_on_j;
            p.torque[i] += out.torque_i;
            p.stress[i].noalias()
              -= in.lever_i * (out.force_on_j * in.n.transpose());
            stiffness_sum[i] += out.stiffness;
          }

    // Particle stresses and pressures for the next evaluation; time step.
    double omega2 = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      {
        const double r = p.radius[i];
        p.stress[i] *= 1.0 / (4.0 / 3.0 * pi * r * r * r);
        p.pressure[i] = p.stress[i].trace() / 3.0;
        if (!p.kinematic[i])
          omega2 = std::max(omega2, 2.0 * stiffness_sum[i] * p.inverse_mass[i]);
      }
    if (fixed_dt > 0.0)
      dt = fixed_dt;
    else
      {
        dt = rayleigh_limit();
        if (omega2 > 0.0)
          dt
            = std::min(dt, settings.stiffness_factor * 2.0 / std::sqrt(omega2));
      }
  }

  void
  ExplicitDem::step()
  {
    const double      h = time_step();
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i)
      if (!p.kinematic[i])
        {
          p.velocity[i] += 0.5 * h * p.inverse_mass[i] * p.force[i];
          p.angular_velocity[i] += 0.5 * h * p.inverse_inertia[i] * p.torque[i];
        }
    for (std::size_t i = 0; i < n; ++i)
      p.position[i] += h * p.velocity[i];
    if (plates_enabled)
      for (Plate &plate : plates)
        plate.position += h * plate.velocity;
    update_neighbours(false);
    compute_forces(h);
    for (std::size_t i = 0; i < n; ++i)
      if (!p.kinematic[i])
        {
          p.velocity[i] += 0.5 * h * p.inverse_mass[i] * p.force[i];
          p.angular_velocity[i] += 0.5 * h * p.inverse_inertia[i] * p.torque[i];
        }
    t += h;
    ++step_count;
  }

  double
  ExplicitDem::kinetic_energy() const
  {
    double e = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      e += 0.5 * p.mass[i] * p.velocity[i].squaredNorm()
           + 0.5 / p.inverse_inertia[i] * p.angular_velocity[i].squaredNorm();
    return e;
  }

  double
  ExplicitDem::elastic_energy() const
  {
    if (model)
      throw std::logic_error("ExplicitDem::elastic_energy: the laws of a "
                             "ContactModel declare no stored energy");
    double e = 0.0;
    for (const DynamicPairContact &c : pairs)
      if (c.overlap > 0.0)
        {
          const double R
            = p.radius[c.i] * p.radius[c.j] / (p.radius[c.i] + p.radius[c.j]);
          const MulticontactAdhesiveLaw law(R, E_pp, mat.normal_law);
          e += normal_energy(law, c.overlap, law.delta_max(c.history));
          const double S_t = 8.0 * G_pp * std::sqrt(R * c.overlap);
          e += 0.5 * S_t * c.tangential.squaredNorm();
        }
    if (plates_enabled)
      for (std::size_t i = 0; i < p.size(); ++i)
        for (int w = 0; w < 2; ++w)
          {
            const PlateContact &c = walls[2 * i + w];
            if (c.overlap <= 0.0)
              continue;
            const MulticontactAdhesiveLaw law(p.radius[i],
                                              E_pw,
                                              mat.normal_law);
            e += normal_energy(law, c.overlap, law.delta_max(c.history));
            const double S_t = 8.0 * G_pw * std::sqrt(p.radius[i] * c.overlap);
            e += 0.5 * S_t * c.tangential.squaredNorm();
          }
    return e;
  }

  Eigen::Matrix3d
  ExplicitDem::average_stress(const double volume) const
  {
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        const double r = p.radius[i];
        s += (4.0 / 3.0 * pi * r * r * r) * p.stress[i];
      }
    return s / volume;
  }

  std::size_t
  ExplicitDem::contact_count() const
  {
    std::size_t count = 0;
    for (const DynamicPairContact &c : pairs)
      count += c.overlap > 0.0;
    return count;
  }

  std::size_t
  ExplicitDem::wall_contact_count() const
  {
    std::size_t count = 0;
    if (plates_enabled)
      for (const PlateContact &c : walls)
        count += c.overlap > 0.0;
    return count;
  }

  double
  ExplicitDem::solid_volume() const
  {
    double v = 0.0;
    for (const double r : p.radius)
      v += 4.0 / 3.0 * pi * r * r * r;
    return v;
  }
} // namespace compax::dem
