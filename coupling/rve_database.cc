#include "coupling/rve_database.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace compax::coupling
{
  namespace
  {
    using dem::PeriodicBed;

    Eigen::Matrix3d
    axial(const double eps_zz)
    {
      Eigen::Matrix3d e = Eigen::Matrix3d::Zero();
      e(2, 2)           = eps_zz;
      return e;
    }

    /// Runs one step; throws if it does not converge.
    void
    step(dem::RveLoading       &loading,
         PeriodicBed           &bed,
         const Eigen::Matrix3d &strain,
         const std::string     &what)
    {
      if (!loading.apply_strain(bed, strain).converged)
        throw std::runtime_error("RVE database: " + what
                                 + " step did not converge at density "
                                 + std::to_string(bed.relative_density()));
    }

    void
    record(RveDatabase       &db,
           const int          branch,
           const std::string &path,
           const PeriodicBed &bed,
           const double       shear = 0.0)
    {
      db.rows.push_back({branch,
                         path,
                         bed.relative_density(),
                         shear,
                         dem::to_voigt(dem::love_weber_stress(bed))});
    }

    /// Constant-volume shear gamma_xz from `bed`. The failure state is the
    /// mean (p, q) over the second half of the probe: past the peak a
    /// small cell's q jumps from bond to bond, and its plateau (the
    /// shear strength at that pressure) is steadier than its maximum.
    StressInvariants
    shear_probe(const DatabaseSpec      &spec,
                const dem::ContactModel &model,
                PeriodicBed              bed,
                RveDatabase             &db,
                const int                branch,
                const std::string       &path)
    {
      dem::RveLoading loading(model, spec.loading);
      const double    dg = spec.shear_strain / spec.shear_steps;
      Eigen::Matrix3d e  = Eigen::Matrix3d::Zero();
      e(0, 2) = e(2, 0) = 0.5 * dg;
      StressInvariants plateau{0.0, 0.0};
      int              n = 0;
      for (int k = 1; k <= spec.shear_steps; ++k)
        {
          step(loading, bed, e, path);
          record(db, branch, path, bed, k * dg);
          if (2 * k > spec.shear_steps)
            {
              const StressInvariants s = invariants(db.rows.back().stress);
              plateau.p += s.p;
              plateau.q += s.q;
              ++n;
            }
        }
      return {plateau.p / n, plateau.q / n};
    }
  } // namespace

  StressInvariants
  invariants(const dem::Vector6d &s)
  {
    const double p  = -(s[0] + s[1] + s[2]) / 3.0;
    const double dx = s[0] + p, dy = s[1] + p, dz = s[2] + p;
    const double j2 = 0.5 * (dx * dx + dy * dy + dz * dz) + s[3] * s[3]
                      + s[4] * s[4] + s[5] * s[5];
    return {p, std::sqrt(3.0 * j2)};
  }

  RveDatabase
  build_rve_database(const DatabaseSpec                     &spec,
                     const dem::ContactModel                &model,
                     const std::function<void(std::string)> &progress)
  {
    auto say = [&](const std::string &line) {
      if (progress)
        progress(line);
    };
    RveDatabase     db;
    PeriodicBed     bed = dem::make_periodic_packing(spec.packing, model);
    dem::RveLoading loading(model, spec.loading);
    dem::TangentCalculator tangent;
    record(db, -1, "compaction", bed);
    std::size_t next_branch = 0;
    while (bed.relative_density() < spec.final_density * (1.0 - 1e-12))
      {
        double target
          = std::min(bed.relative_density() * std::exp(spec.strain_step),
                     spec.final_density);
        if (next_branch < spec.branch_densities.size())
          target = std::min(target, spec.branch_densities[next_branch]);
        step(loading,
             bed,
             axial(-std::log(target / bed.relative_density())),
             "compaction");
        record(db, -1, "compaction", bed);
        std::ostringstream line;
        line << "compaction  rho " << bed.relative_density() << "  sigma_zz "
             << db.rows.back().stress[2] / 1e6 << " MPa";
        say(line.str());

        if (next_branch < spec.branch_densities.size()
            && bed.relative_density()
                 >= spec.branch_densities[next_branch] * (1.0 - 1e-12))
          {
            const int      b = static_cast<int>(next_branch++);
            DatabaseBranch br;
            br.relative_density = bed.relative_density();
            br.loaded_stress    = db.rows.back().stress;
            PeriodicBed probe   = bed;

            // Axial unloading until the cell carries no axial stress.
            dem::RveLoading unloading(model, spec.loading);
            for (int k = 0; k < 200 && db.rows.back().stress[2] < 0.0; ++k)
              {
                step(unloading,
                     probe,
                     axial(0.25 * spec.strain_step),
                     "unloading");
                record(db, b, "unloading", probe);
              }
            br.unloaded_density       = probe.relative_density();
            const dem::CellTangents t = tangent.compute(probe, model);
            br.elastic                = isotropic_projection(
              0.5 * (t.condensed + t.condensed.transpose()));

            br.shear_failure = shear_probe(spec, model, probe, db, b, "shear");
            PeriodicBed     confined = probe;
            Eigen::Matrix3d v
              = -spec.confinement_strain / 3.0 * Eigen::Matrix3d::Identity();
            step(unloading, confined, v, "confinement");
            br.confined_shear_failure
              = shear_probe(spec, model, confined, db, b, "confined_shear");
            db.branches.push_back(br);
            std::ostringstream done;
            done << "branch " << b << "  rho " << br.relative_density << "  E "
                 << br.elastic.youngs_modulus / 1e9 << " GPa  nu "
                 << br.elastic.poisson_ratio << "  shear failure q "
                 << br.shear_failure.q / 1e6 << " / "
                 << br.confined_shear_failure.q / 1e6 << " MPa";
            say(done.str());
          }
      }
    return db;
  }

  std::vector<DpcFitRow>
  fit_drucker_prager_cap(const RveDatabase &db, std::vector<std::string> *notes)
  {
    std::vector<DpcFitRow> rows;
    for (const DatabaseBranch &b : db.branches)
      {
        ShearLine line{0.0, 0.0};
        bool      line_ok = false;
        try
          {
            line
              = shear_line_through(b.shear_failure, b.confined_shear_failure);
            line_ok = line.tan_friction_angle > 0.0 && line.cohesion >= 0.0;
          }
        catch (const std::domain_error &)
          {
          }
        if (!line_ok)
          {
            // Through the higher-pressure failure with d = 0.
            const StressInvariants &f
              = b.shear_failure.p > b.confined_shear_failure.p
                  ? b.shear_failure
                  : b.confined_shear_failure;
            line = {0.0, f.p > 0.0 ? f.q / f.p : 1.0};
            if (notes)
              notes->push_back(
                "branch at rho " + std::to_string(b.relative_density)
                + ": the two shear failures give no physical line; d = 0"
                  " through the higher-pressure failure");
          }
        const CapParameters cap
          = cap_through_uniaxial_state(invariants(b.loaded_stress), line);
        rows.push_back({b.relative_density,
                        line.cohesion,
                        std::atan(line.tan_friction_angle) * 180.0 / M_PI,
                        cap.eccentricity,
                        cap.cap_pressure,
                        b.elastic.youngs_modulus,
                        b.elastic.poisson_ratio});
      }
    return rows;
  }
} // namespace compax::coupling
