#include "dem/dynamics/uniaxial_compaction.h"

#include "dem/periodic/random_insertion.h"
#include "dem/wall_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace compax::dem
{
  namespace
  {
    /// Calls the progress callback about every half second of wall time.
    class Throttle
    {
    public:
      bool
      due()
      {
        const auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - last).count() < 0.5)
          return false;
        last = now;
        return true;
      }

    private:
      std::chrono::steady_clock::time_point last
        = std::chrono::steady_clock::now();
    };
  } // namespace

  UniaxialCompaction::UniaxialCompaction(const DemMaterial      &material,
                                         const DynamicsSettings &settings,
                                         const RveSpec          &rve)
      : material(material)
      , settings(settings)
      , rve(rve)
  {
  }

  UniaxialCompaction::UniaxialCompaction(const UniaxialCompaction &other)
      : material(other.material)
      , settings(other.settings)
      , rve(other.rve)
      , box_lengths(other.box_lengths)
      , system(other.system ? std::make_unique<ExplicitDem>(*other.system)
                            : nullptr)
      , full_radii(other.full_radii)
      , summary(other.summary)
  {
  }

  void
  UniaxialCompaction::prepare(const CompactionProtocol &protocol,
                              const ProgressCallback   &progress)
  {
    const auto    start = std::chrono::steady_clock::now();
    RandomSource  random(rve.seed);
    InsertionSpec spec;
    spec.box                         = Eigen::Vector3d::Constant(rve.cell_size);
    spec.packing_density             = rve.packing_density;
    spec.sizes                       = rve.sizes;
    spec.particle_count              = rve.particle_count;
    spec.initial_scale               = rve.initial_scale;
    const InsertedParticles inserted = insert_random(spec, random);
    box_lengths                      = inserted.box;
    full_radii                       = inserted.radii;

    system = std::make_unique<ExplicitDem>(
      material, PeriodicCell::box(box_lengths, {true, true, false}), settings);
    for (std::size_t k = 0; k < inserted.radii.size(); ++k)
      system->add_particle(inserted.positions[k],
                           rve.initial_scale * inserted.radii[k]);
    system->add_plates(0.0, box_lengths[2]);

    // Grow with the conventional elastic, frictionless law.
    system->set_normal_law(MulticontactAdhesiveLaw::Parameters{});
    system->set_friction(false);
    Throttle     throttle;
    const double t0        = system->time();
    const double T         = protocol.growth_time;
    auto        &particles = system->particles();
    while (system->time() - t0 < T)
      {
        const double f = std::min(1.0, (system->time() - t0) / T);
        const double s = rve.initial_scale + (1.0 - rve.initial_scale) * f;
        for (std::size_t k = 0; k < full_radii.size(); ++k)
          system->set_radius(k, s * full_radii[k]);
        system->step();
        summary.particle_steps += particles.size();
        if (progress && throttle.due())
          progress({"growth", f, 0.0, 0.0, system->steps()});
      }
    for (std::size_t k = 0; k < full_radii.size(); ++k)
      system->set_radius(k, full_radii[k]);
    const double t1 = system->time();
    while (system->time() - t1 < protocol.relaxation_time)
      {
        system->step();
        summary.particle_steps += particles.size();
        if (progress && throttle.due())
          progress({"relaxation",
                    (system->time() - t1) / protocol.relaxation_time,
                    0.0,
                    0.0,
                    system->steps()});
      }
    system->set_normal_law(material.normal_law);
    system->set_friction(true);
    system->reset_contact_history();
    summary.particles       = particles.size();
    summary.initial_density = system->solid_volume() / box_lengths.prod();
    summary.wall_seconds += seconds_since(start);
  }

  CompactionRecord
  UniaxialCompaction::measure(const int    stage,
                              const double strain,
                              const double stress)
  {
    ExplicitDem &s      = *system;
    const double height = s.top_plate().position - s.bottom_plate().position;
    const double volume = box_lengths[0] * box_lengths[1] * height;
    const auto  &p      = s.particles();
    double       mean_p = 0.0;
    for (const double q : p.pressure)
      mean_p -= q;
    const std::size_t n = p.size();
    CompactionRecord  r;
    r.time             = 0.0;
    r.stage            = stage;
    r.strain           = strain;
    r.stress_zz        = stress;
    r.stress_zz_bulk   = -s.average_stress(volume)(2, 2);
    r.relative_density = s.solid_volume() / volume;
    r.kinetic_energy   = s.kinetic_energy();
    r.elastic_energy   = s.elastic_energy();
    r.coordination     = (2.0 * s.contact_count() + s.wall_contact_count())
                     / std::max<std::size_t>(n, 1);
    r.mean_pressure = mean_p / std::max<std::size_t>(n, 1);
    r.time_step     = s.time_step();
    return r;
  }

  CompactionSummary
  UniaxialCompaction::compact(const CompactionProtocol &protocol,
                              const RecordCallback     &record,
                              const ProgressCallback   &progress)
  {
    if (!system)
      throw std::logic_error("UniaxialCompaction: prepare() first");
    if (!(protocol.strain_rate > 0.0 && protocol.target_strain > 0.0
          && protocol.target_strain < 1.0))
      throw std::invalid_argument("compaction: bad strain rate or target");
    const auto        start = std::chrono::steady_clock::now();
    ExplicitDem      &s     = *system;
    const double      H0   = s.top_plate().position - s.bottom_plate().position;
    const double      area = box_lengths[0] * box_lengths[1];
    const double      speed = protocol.strain_rate * H0;
    const double      t0    = s.time();
    const std::size_t n     = s.particles().size();

    auto strain_now = [&] {
      return (H0 - (s.top_plate().position - s.bottom_plate().position)) / H0;
    };
    auto stress_now = [&] {
      return 0.5 * (s.top_plate().force[2] - s.bottom_plate().force[2]) / area;
    };

    Throttle throttle;
    // Time-averaged plate stress over each output interval.
    double stress_integral = 0.0, interval_time = 0.0;
    // Loading rows carry the interval mean (it filters the plate's contact
    // chatter); unloading rows the instantaneous stress, which falls to
    // zero within a fraction of an interval.
    auto emit = [&](const int stage) {
      const double     stress = stage == 1 && interval_time > 0.0
                                  ? stress_integral / interval_time
                                  : stress_now();
      CompactionRecord r      = measure(stage, strain_now(), stress);
      r.time                  = s.time() - t0;
      record(r);
      stress_integral = 0.0;
      interval_time   = 0.0;
      return r;
    };

    // One explicit step, counted and added to the interval's stress
    // integral; returns the strain it reaches.
    auto advance = [&] {
      const double h = s.time_step();
      s.step();
      summary.particle_steps += n;
      stress_integral += h * stress_now();
      interval_time += h;
      return strain_now();
    };

    (void)s.time_step(); // forces of the initial state
    emit(1);
    double next_output     = protocol.output_strain_interval;
    s.top_plate().velocity = -speed;
    for (;;)
      {
        const double e      = advance();
        const double sigma  = stress_now();
        summary.peak_strain = std::max(summary.peak_strain, e);
        summary.peak_stress = std::max(summary.peak_stress, sigma);
        const bool done     = e >= protocol.target_strain
                          || (protocol.target_stress > 0.0
                              && sigma >= protocol.target_stress);
        if (e >= next_output || done)
          {
            emit(1);
            while (next_output <= e)
              next_output += protocol.output_strain_interval;
          }
        if (progress && throttle.due())
          progress({"compression",
                    std::min(1.0, e / protocol.target_strain),
                    e,
                    sigma,
                    s.steps()});
        if (done)
          break;
      }
    if (protocol.decompress)
      {
        s.top_plate().velocity = speed;
        const double peak      = strain_now();
        double       next      = peak - protocol.output_strain_interval;
        for (;;)
          {
            const double e    = advance();
            const bool   done = stress_now() <= 0.0 || e <= 0.0;
            if (e <= next || done)
              {
                emit(2);
                while (next >= e)
                  next -= protocol.output_strain_interval;
              }
            if (progress && throttle.due())
              progress({"decompression",
                        std::min(1.0, (peak - e) / std::max(peak, 1e-12)),
                        e,
                        stress_now(),
                        s.steps()});
            if (done)
              {
                summary.residual_strain = std::max(e, 0.0);
                break;
              }
          }
      }
    s.top_plate().velocity = 0.0;
    summary.steps          = s.steps();
    summary.wall_seconds += seconds_since(start);
    return summary;
  }
} // namespace compax::dem
