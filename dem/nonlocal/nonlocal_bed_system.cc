#include "dem/nonlocal/nonlocal_bed_system.h"

#include "dem/contact/pair_properties.h"
#include "dem/numbers.h"
#include "dem/solver/pair_block.h"
#include "dem/solver/step_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>

namespace compax::dem
{
  namespace
  {
    template <typename Key>
    bool
    less(const Key &a, const Key &b)
    {
      if (a.i != b.i)
        return a.i < b.i;
      if (a.j != b.j)
        return a.j < b.j;
      return a.image < b.image;
    }

    /// No walls (a periodic cell).
    class NoWalls final : public FlatWalls
    {
    public:
      int
      n_walls() const override
      {
        return 0;
      }

      double
      distance(int, const Eigen::Vector3d &) const override
      {
        return std::numeric_limits<double>::infinity();
      }

      Eigen::Vector3d
      outward_normal(int, const Eigen::Vector3d &) const override
      {
        return Eigen::Vector3d::Zero();
      }

      double
      position(int) const override
      {
        return 0.0;
      }

      int
      sums_slot(int) const override
      {
        return 2;
      }
    };
  } // namespace

  NonlocalBedSystem::NonlocalBedSystem(
    ParticleSystem                     &particles,
    const std::vector<ElasticMaterial> &materials,
    const SquareDie                    &die,
    const NonlocalBedOptions            options)
      : NonlocalBedSystem(particles,
                          materials,
                          std::make_unique<SquareDieWalls>(die),
                          options)
  {
  }

  NonlocalBedSystem::NonlocalBedSystem(
    ParticleSystem                     &particles,
    const std::vector<ElasticMaterial> &materials,
    const DieWalls                     &die,
    const NonlocalBedOptions            options)
      : NonlocalBedSystem(particles,
                          materials,
                          std::make_unique<CylinderDieWalls>(die),
                          options)
  {
  }

  NonlocalBedSystem::NonlocalBedSystem(
    ParticleSystem                     &particles,
    const std::vector<ElasticMaterial> &materials,
    std::unique_ptr<NonlocalWalls>      walls_,
    const NonlocalBedOptions            options)
      : particles(particles)
      , materials(materials)
      , walls(std::move(walls_))
      , opts(options)
      , r_mean(particles.mean_radius())
      , skin_(options.skin * particles.mean_radius())
  {
    if (!opts.local_laws)
      return;
    const ContactModel &model = *opts.local_laws;
    if (model.n_materials() < materials.size())
      throw std::invalid_argument("NonlocalBedSystem: the local laws know "
                                  + std::to_string(model.n_materials())
                                  + " materials, the bed has "
                                  + std::to_string(materials.size()));
    const ParticleLaw law = model.wall_law(0, r_mean);
    if (!elastic_law(law))
      throw std::invalid_argument(
        "the nonlocal formulation (Gonzalez & Cuitino 2012) needs an "
        "elastic local law; "
        + std::visit([](const auto &l) { return l.name(); }, law)
        + " keeps internal variables");
  }

  NonlocalBedSystem::NonlocalBedSystem(
    ParticleSystem                     &particles,
    const std::vector<ElasticMaterial> &materials,
    const PeriodicCell                 &cell_,
    const NonlocalBedOptions            options)
      : NonlocalBedSystem(particles,
                          materials,
                          std::make_unique<NoWalls>(),
                          options)
  {
    cell = &cell_;
  }

  void
  NonlocalBedSystem::set_nonlocal(const bool nonlocal)
  {
    opts.nonlocal = nonlocal;
    std::fill(gamma_nl.begin(), gamma_nl.end(), 0.0);
  }

  void
  NonlocalBedSystem::update_list()
  {
    const std::size_t N           = particles.size();
    bool              rebuild_now = dirty || reference.size() != N;
    for (int f = 0; f < walls->n_walls() && !rebuild_now; ++f)
      rebuild_now = walls->position(f) != reference_walls[f];
    if (cell && !rebuild_now)
      rebuild_now = cell->lattice() != reference_lattice;
    const double limit = 0.25 * skin_ * skin_;
    for (std::size_t i = 0; i < N && !rebuild_now; ++i)
      rebuild_now
        = (particles.positions[i] - reference[i]).squaredNorm() > limit;
    if (rebuild_now)
      rebuild();
  }

  void
  NonlocalBedSystem::rebuild()
  {
    const std::size_t N = particles.size();
    old_keys.swap(keys);
    old_gamma_nl.swap(gamma_nl);
    keys.clear();
    if (cell)
      {
        periodic_grid.find_pairs(
          *cell, particles.positions, particles.radii, skin_, image_pairs);
        for (const ImagePair &q : image_pairs)
          keys.push_back({q.i, q.j, q.image});
        candidate_pairs.clear();
      }
    else
      grid.find_pairs(particles.positions,
                      particles.radii,
                      skin_,
                      candidate_pairs);
    std::size_t next = 0;
    for (std::uint32_t i = 0; i < N; ++i)
      {
        for (;
             next < candidate_pairs.size() && candidate_pairs[next].first == i;
             ++next)
          keys.push_back({i, candidate_pairs[next].second});
        for (int f = 0; f < walls->n_walls(); ++f)
          if (walls->distance(f, particles.positions[i])
              < particles.radii[i] + skin_)
            keys.push_back({i, static_cast<std::uint32_t>(N + f)});
      }
    const std::size_t n = keys.size();

    // The local law of every candidate: the chosen elastic law, or Hertz's
    // (Eq. 9).
    laws.clear();
    laws.reserve(n);
    for (std::size_t c = 0; c < n; ++c)
      {
        const Key         &k  = keys[c];
        const unsigned int ai = particles.materials[k.i];
        if (opts.local_laws)
          {
            laws.push_back(
              k.j < N ? opts.local_laws->pair_law(ai,
                                                  particles.radii[k.i],
                                                  particles.materials[k.j],
                                                  particles.radii[k.j])
                      : opts.local_laws->wall_law(ai, particles.radii[k.i]));
            continue;
          }
        const ElasticMaterial &mi = materials[ai];
        double                 R, E;
        if (k.j < N)
          {
            const ElasticMaterial &mj = materials[particles.materials[k.j]];
            R = effective_radius(particles.radii[k.i], particles.radii[k.j]);
            E = effective_modulus(mi.youngs_modulus,
                                  mi.poisson_ratio,
                                  mj.youngs_modulus,
                                  mj.poisson_ratio);
          }
        else
          {
            R = particles.radii[k.i];
            E = effective_modulus(mi.youngs_modulus,
                                  mi.poisson_ratio,
                                  rigid,
                                  0.0);
          }
        laws.emplace_back(HertzLaw(R, E));
      }

    // Warm start: carry gamma_NL of the surviving candidates over (both
    // lists are sorted by (i, j)).
    gamma_nl.assign(n, 0.0);
    if (old_gamma_nl.size() == old_keys.size())
      for (std::size_t c = 0, o = 0; c < n && o < old_keys.size();)
        {
          const Key &k = keys[c], &ko = old_keys[o];
          if (less(ko, k))
            ++o;
          else if (less(k, ko))
            ++c;
          else
            gamma_nl[c++] = old_gamma_nl[o++];
        }

    // Candidates of each particle, CSR by counting sort.
    particle_offset.assign(N + 1, 0);
    for (const Key &k : keys)
      {
        ++particle_offset[k.i + 1];
        if (k.j < N)
          ++particle_offset[k.j + 1];
      }
    for (std::size_t p = 0; p < N; ++p)
      particle_offset[p + 1] += particle_offset[p];
    particle_contacts.resize(particle_offset[N]);
    for (std::size_t c = 0; c < n; ++c)
      {
        particle_contacts[particle_offset[keys[c].i]++] = c;
        if (keys[c].j < N)
          particle_contacts[particle_offset[keys[c].j]++] = c;
      }
    for (std::size_t p = N; p > 0; --p)
      particle_offset[p] = particle_offset[p - 1];
    particle_offset[0] = 0;

    // Incidences: every other candidate on either (deformable) particle.
    incidence_offset.assign(1, 0);
    incidences.clear();
    for (std::size_t c = 0; c < n; ++c)
      {
        for (int side = 0; side < 2; ++side)
          {
            const std::uint32_t p = side == 0 ? keys[c].i : keys[c].j;
            if (p >= N)
              continue; // rigid wall
            for (std::size_t q = particle_offset[p]; q < particle_offset[p + 1];
                 ++q)
              {
                const std::size_t d = particle_contacts[q];
                if (d == c)
                  continue;
                incidences.push_back({static_cast<std::uint32_t>(d),
                                      side == 0 ? 1.0f : -1.0f,
                                      keys[d].i == p ? 1.0f : -1.0f,
                                      p});
              }
          }
        incidence_offset.push_back(incidences.size());
      }

    reference = particles.positions;
    for (int f = 0; f < walls->n_walls(); ++f)
      reference_walls[f] = walls->position(f);
    if (cell)
      reference_lattice = cell->lattice();
    dirty = false;
    ++revision;
  }

  ContactSums
  NonlocalBedSystem::evaluate(Eigen::VectorXd &F)
  {
    const std::size_t N = particles.size();
    F.setZero(3 * N);
    ContactSums sums;
    wall_force.fill(0.0);
    n_loaded_       = 0;
    n_loaded_pairs_ = 0;
    if (!particles.coordinates().allFinite())
      {
        F.setConstant(std::numeric_limits<double>::quiet_NaN());
        sums.mean_force = std::numeric_limits<double>::quiet_NaN();
        return sums;
      }
    update_list();
    const std::size_t n = keys.size();
    gamma.resize(n);
    distance.resize(n);
    normal.resize(n);
    force.resize(n);
    stiffness.resize(n);
    dcompliance.resize(incidences.size());

    // Geometry: overlap and the normal from i towards j (into the wall).
    for (std::size_t c = 0; c < n; ++c)
      {
        const Key             &k  = keys[c];
        const Eigen::Vector3d &xi = particles.positions[k.i];
        if (k.j < N)
          {
            const Eigen::Vector3d d
              = cell ? Eigen::Vector3d(particles.positions[k.j]
                                       + cell->image_offset(k.image) - xi)
                     : Eigen::Vector3d(particles.positions[k.j] - xi);
            const double dist = d.norm();
            distance[c]       = dist;
            normal[c]         = d / dist;
            gamma[c] = particles.radii[k.i] + particles.radii[k.j] - dist;
          }
        else
          {
            const int f = static_cast<int>(k.j - N);
            distance[c] = walls->distance(f, xi);
            normal[c]   = walls->outward_normal(f, xi);
            gamma[c]    = particles.radii[k.i] - distance[c];
          }
      }

    if (opts.nonlocal)
      {
        // Influence coefficients of Eq. (5) at the current angles, and
        // their derivatives with respect to cos(theta), for apply_jacobian.
        network.clear();
        for (std::size_t c = 0; c < n; ++c)
          {
            network.add_contact(laws[c]);
            for (std::size_t q = incidence_offset[c];
                 q < incidence_offset[c + 1];
                 ++q)
              {
                const Incidence       &in = incidences[q];
                const ElasticMaterial &m
                  = materials[particles.materials[in.body]];
                const double nu = m.poisson_ratio;
                const double k
                  = (1.0 + nu)
                    / (4.0 * pi * particles.radii[in.body] * m.youngs_modulus);
                const double mu
                  = std::clamp(static_cast<double>(in.sign_c) * in.sign_d
                                 * normal[c].dot(normal[in.d]),
                               -1.0,
                               1.0);
                // h = sin(theta / 2) = sqrt((1 - cos theta) / 2).
                const double h = std::sqrt(std::max(0.5 * (1.0 - mu), 1e-30));
                network.add_influence(in.d,
                                      k
                                        * (-2.0 * (1.0 - nu) / h
                                           - 2.0 * (1.0 - 2.0 * nu)
                                           + (7.0 - 8.0 * nu) * h));
                dcompliance[q]
                  = -k * (2.0 * (1.0 - nu) / (h * h) + (7.0 - 8.0 * nu))
                    / (4.0 * h);
              }
          }
        fixed_point_
          = solve_nonlocal_fixed_point(network,
                                       gamma,
                                       gamma_nl,
                                       force,
                                       opts.fixed_point_tolerance * r_mean,
                                       opts.max_fixed_point_iterations,
                                       opts.warm_start);
        total_sweeps_ += fixed_point_.iterations;
        if (!fixed_point_.converged)
          {
            // Beyond the limit point: no equilibrium forces exist here.
            std::fill(gamma_nl.begin(), gamma_nl.end(), 0.0);
            F.setConstant(std::numeric_limits<double>::quiet_NaN());
            sums.mean_force = std::numeric_limits<double>::quiet_NaN();
            return sums;
          }
      }
    else
      {
        gamma_nl.assign(n, 0.0);
        fixed_point_ = {0, true, 0.0};
      }

    double sum_abs = 0.0;
    for (std::size_t c = 0; c < n; ++c)
      {
        // The local law's force and stiffness come from one evaluation;
        // the nonlocal force is the fixed point's.
        const auto response = law_response(laws[c], gamma[c] + gamma_nl[c], {});
        stiffness[c]        = response.stiffness;
        if (!opts.nonlocal)
          force[c] = response.force;
        const double P = force[c];
        if (P == 0.0)
          continue;
        const Key &k = keys[c];
        F.segment<3>(3 * k.i) += P * normal[c];
        if (k.j < N)
          {
            F.segment<3>(3 * k.j) -= P * normal[c];
            ++n_loaded_pairs_;
          }
        else
          wall_force[k.j - N] += P;
        ++n_loaded_;
        sum_abs += std::abs(P);
      }
    for (int f = 0; f < walls->n_walls(); ++f)
      sums.wall_force[walls->sums_slot(f)] += wall_force[f];
    sums.n_loaded = n_loaded_;
    if (n_loaded_ > 0)
      sums.mean_force = sum_abs / n_loaded_;
    return sums;
  }

  ContactSums
  NonlocalBedSystem::residual(Eigen::VectorXd &F)
  {
    return evaluate(F);
  }

  ContactSums
  NonlocalBedSystem::assemble(Eigen::VectorXd &F, BlockSparseMatrix &K)
  {
    const ContactSums sums = evaluate(F);
    const std::size_t N    = particles.size();
    if (pattern_revision != revision || pattern_matrix != &K
        || K.n_block_rows() != N)
      {
        pattern_pairs.clear();
        for (const Key &k : keys)
          if (k.j < N)
            pattern_pairs.emplace_back(k.i, k.j);
        K.reinit(N, pattern_pairs);
        pair_slots.resize(2 * keys.size());
        for (std::size_t c = 0; c < keys.size(); ++c)
          if (keys[c].j < N)
            {
              pair_slots[2 * c]     = K.slot(keys[c].i, keys[c].j);
              pair_slots[2 * c + 1] = K.slot(keys[c].j, keys[c].i);
            }
        pattern_revision = revision;
        pattern_matrix   = &K;
      }
    K.set_zero();
    if (!F.allFinite())
      return sums;
    for (std::size_t c = 0; c < keys.size(); ++c)
      {
        if (force[c] == 0.0 && stiffness[c] == 0.0)
          continue;
        const Key &k = keys[c];
        if (k.j < N)
          {
            const PairBlock blk(ContactResponse{force[c], stiffness[c], 0.0},
                                distance[c]);
            blk.add_to(K.block(K.diagonal_slot(k.i)), 1.0, normal[c]);
            blk.add_to(K.block(K.diagonal_slot(k.j)), 1.0, normal[c]);
            blk.add_to(K.block(pair_slots[2 * c]), -1.0, normal[c]);
            blk.add_to(K.block(pair_slots[2 * c + 1]), -1.0, normal[c]);
          }
        else
          {
            // k n n^T + P dn/dx (the turning normal of a curved wall).
            double *blk = K.block(K.diagonal_slot(k.i));
            for (int s = 0; s < 3; ++s)
              {
                const Eigen::Vector3d dn_s
                  = force[c] == 0.0
                      ? Eigen::Vector3d::Zero()
                      : walls->normal_derivative(static_cast<int>(k.j - N),
                                                 particles.positions[k.i],
                                                 Eigen::Vector3d::Unit(s));
                for (int r = 0; r < 3; ++r)
                  blk[3 * r + s] += stiffness[c] * normal[c][r] * normal[c][s]
                                    + force[c] * dn_s[r];
              }
          }
      }
    return sums;
  }

  bool
  NonlocalBedSystem::limit_closing(const Eigen::VectorXd &s,
                                   Eigen::VectorXd       &factor) const
  {
    const std::size_t N = particles.size();
    MeanOverlap       mean;
    for (std::size_t c = 0; c < keys.size() && c < force.size(); ++c)
      if (force[c] > 0.0)
        mean.add(gamma[c]);
    const double allowance = mean.value(1e-3 * r_mean);
    bool         clipped   = false;
    for (std::size_t c = 0; c < keys.size() && c < force.size(); ++c)
      {
        if (force[c] > 0.0)
          continue; // the quadratic model sees it
        const Key   &k   = keys[c];
        const double gap = std::max(0.0, -(gamma[c] + gamma_nl[c]));
        if (k.j < N)
          {
            const double closing
              = normal[c].dot(s.segment<3>(3 * k.i) - s.segment<3>(3 * k.j));
            clipped |= limit_step_to_gap(factor, k.i, gap, closing, allowance);
            clipped |= limit_step_to_gap(factor, k.j, gap, closing, allowance);
          }
        else
          clipped |= limit_step_to_gap(
            factor, k.i, gap, normal[c].dot(s.segment<3>(3 * k.i)), allowance);
      }
    return clipped;
  }

  void
  NonlocalBedSystem::apply_jacobian(const Eigen::VectorXd &v,
                                    Eigen::VectorXd       &Jv,
                                    const bool             turning)
  {
    const std::size_t N = particles.size();
    const std::size_t n = keys.size();
    a.resize(n);
    y.resize(n);
    y_new.resize(n);
    dn.resize(n);
    // d gamma and the turning of the normals.
    for (std::size_t c = 0; c < n; ++c)
      {
        const Key             &k  = keys[c];
        const Eigen::Vector3d &nc = normal[c];
        if (k.j < N)
          {
            const Eigen::Vector3d dv
              = v.segment<3>(3 * k.j) - v.segment<3>(3 * k.i);
            dn[c] = (dv - nc * nc.dot(dv)) / distance[c];
            a[c]  = -nc.dot(dv);
          }
        else
          {
            dn[c] = walls->normal_derivative(static_cast<int>(k.j - N),
                                             particles.positions[k.i],
                                             v.segment<3>(3 * k.i));
            a[c]  = nc.dot(v.segment<3>(3 * k.i));
          }
      }
    if (opts.nonlocal)
      {
        // a = d gamma + dC P.
        const auto &compliance = network.compliance();
        for (std::size_t c = 0; c < n && turning; ++c)
          for (std::size_t q = incidence_offset[c]; q < incidence_offset[c + 1];
               ++q)
            {
              const Incidence &in = incidences[q];
              if (force[in.d] == 0.0)
                continue;
              const double dmu
                = static_cast<double>(in.sign_c) * in.sign_d
                  * (dn[c].dot(normal[in.d]) + normal[c].dot(dn[in.d]));
              a[c] += dcompliance[q] * dmu * force[in.d];
            }
        // (I - D C) y = D a by the same Jacobi iteration as Algorithm 1
        // (its linearization, which contracts wherever Algorithm 1 does).
        double scale = 0.0;
        for (std::size_t c = 0; c < n; ++c)
          {
            y[c]  = stiffness[c] * a[c];
            scale = std::max(scale, std::abs(y[c]));
          }
        for (int sweep = 0; sweep < 100000 && scale > 0.0; ++sweep)
          {
            double change = 0.0;
            for (std::size_t c = 0; c < n; ++c)
              {
                if (stiffness[c] == 0.0)
                  {
                    y_new[c] = 0.0;
                    continue;
                  }
                double sum = a[c];
                for (std::size_t q = incidence_offset[c];
                     q < incidence_offset[c + 1];
                     ++q)
                  sum += compliance[q] * y[incidences[q].d];
                y_new[c] = stiffness[c] * sum;
                change   = std::max(change, std::abs(y_new[c] - y[c]));
              }
            y.swap(y_new);
            scale = 0.0;
            for (std::size_t c = 0; c < n; ++c)
              scale = std::max(scale, std::abs(y[c]));
            if (!(change > 1e-15 * scale))
              break;
          }
      }
    else
      for (std::size_t c = 0; c < n; ++c)
        y[c] = stiffness[c] * a[c];

    // dF = sum_c dP_c g_c + P_c dg_c.
    Jv.setZero(3 * N);
    for (std::size_t c = 0; c < n; ++c)
      {
        const Key            &k = keys[c];
        const Eigen::Vector3d t = y[c] * normal[c] + force[c] * dn[c];
        Jv.segment<3>(3 * k.i) += t;
        if (k.j < N)
          Jv.segment<3>(3 * k.j) -= t;
      }
  }

  Eigen::Matrix3d
  NonlocalBedSystem::stress() const
  {
    Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
    if (!cell)
      return S;
    const std::size_t N = particles.size();
    for (std::size_t c = 0; c < keys.size() && c < force.size(); ++c)
      if (keys[c].j < N && force[c] != 0.0)
        S.noalias()
          -= (force[c] * distance[c]) * normal[c] * normal[c].transpose();
    return S / cell->volume();
  }

  double
  NonlocalBedSystem::max_nonlocal_ratio() const
  {
    double m = 0.0;
    for (std::size_t c = 0; c < force.size() && c < gamma_nl.size(); ++c)
      if (force[c] > 0.0 && gamma[c] > 0.0)
        m = std::max(m, std::abs(gamma_nl[c]) / gamma[c]);
    return m;
  }
} // namespace compax::dem
