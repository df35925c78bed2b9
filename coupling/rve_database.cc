#include "coupling/rve_database.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
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

    /// Appends the state of `bed`, reached from row `parent`; returns its
    /// index.
    int
    record(RveDatabase       &db,
           const int          branch,
           const std::string &path,
           const PeriodicBed &bed,
           const int          parent,
           const double       shear = 0.0)
    {
      DatabaseRow row{branch,
                      path,
                      bed.relative_density(),
                      shear,
                      dem::to_voigt(dem::love_weber_stress(bed))};
      row.deformation = bed.deformation;
      row.parent      = parent;
      db.rows.push_back(row);
      return static_cast<int>(db.rows.size()) - 1;
    }

    /// Constant-volume shear gamma_xz from `bed` (state of row `from`).
    /// The failure state is the mean (p, q) over the second half of the
    /// probe: past the peak a small cell's q jumps from bond to bond, and
    /// its plateau (the shear strength at that pressure) is steadier than
    /// its maximum.
    StressInvariants
    shear_probe(const DatabaseSpec      &spec,
                const dem::ContactModel &model,
                PeriodicBed              bed,
                RveDatabase             &db,
                const int                branch,
                const std::string       &path,
                int                      from,
                const bool               jammed)
    {
      dem::RveLoading loading(model, spec.loading);
      if (jammed)
        loading.set_jammed();
      const double    dg = spec.shear_strain / spec.shear_steps;
      Eigen::Matrix3d e  = Eigen::Matrix3d::Zero();
      e(0, 2) = e(2, 0) = 0.5 * dg;
      StressInvariants plateau{0.0, 0.0};
      int              n = 0;
      for (int k = 1; k <= spec.shear_steps; ++k)
        {
          step(loading, bed, e, path);
          from = record(db, branch, path, bed, from, k * dg);
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

    /// Radial-strain probe eps_xx = eps_yy = k eps_zz, eps_zz compressive,
    /// from `bed` (state of row `from`).
    void
    radial_probe(const DatabaseSpec      &spec,
                 const dem::ContactModel &model,
                 PeriodicBed              bed,
                 RveDatabase             &db,
                 const int                branch,
                 const double             k,
                 int                      from,
                 const bool               jammed)
    {
      dem::RveLoading loading(model, spec.loading);
      if (jammed)
        loading.set_jammed();
      const std::string path = radial_path_name(k);
      // A logarithmic strain increment per step, applied as F <- exp(e) F
      // (diagonal, so exactly): after n steps eps_zz = -n de.
      const double    de = spec.radial_strain / spec.radial_steps;
      Eigen::Matrix3d e  = Eigen::Matrix3d::Zero();
      e(0, 0) = e(1, 1) = std::expm1(-k * de);
      e(2, 2)           = std::expm1(-de);
      for (int s = 1; s <= spec.radial_steps; ++s)
        {
          step(loading, bed, e, path);
          from = record(db, branch, path, bed, from);
        }
    }
  } // namespace

  bool
  is_training_path(const std::string &path)
  {
    return path.rfind("radial_", 0) != 0;
  }

  std::string
  radial_path_name(const double k)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "radial_%.2f", k);
    return buffer;
  }

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
                     const std::function<void(std::string)> &progress,
                     const DatabaseControl                  &control)
  {
    auto say = [&](const std::string &line) {
      if (progress)
        progress(line);
    };
    const std::size_t n_branches = spec.branch_densities.size();
    const std::size_t n_paths
      = 1 + n_branches * (4 + spec.radial_ratios.size());
    // The compaction path is path 1, reported in segments between branches.
    std::size_t paths_done = 1;
    auto        path_done  = [&](const int          b,
                         const std::string &path,
                         const RveDatabase &db,
                         const std::size_t  steps) {
      if (path != "compaction")
        ++paths_done;
      const StressInvariants s = invariants(db.rows.back().stress);
      std::ostringstream     line;
      line << "path " << (path == "compaction" ? 1 : paths_done) << "/"
           << n_paths << "  branch " << b << " " << path << ": " << steps
           << " steps, end rho " << db.rows.back().relative_density << "  p "
           << s.p / 1e6 << " MPa  q " << s.q / 1e6 << " MPa";
      say(line.str());
    };

    RveDatabase db;
    PeriodicBed bed;
    if (control.resume)
      {
        db         = control.resume->database;
        db.stopped = false;
        bed        = control.resume->bed;
        paths_done = 1 + db.branches.size() * (4 + spec.radial_ratios.size());
        std::ostringstream line;
        line << "resumed after branch " << db.branches.size() << " of "
             << n_branches << " at rho " << bed.relative_density() << " ("
             << db.rows.size() << " rows)";
        say(line.str());
      }
    else
      {
        bed = dem::make_rve_packing(
          spec.packing, model, spec.loading, 2, spec.denser_deposit);
        record(db, -1, "compaction", bed, -1);
      }
    auto loading = std::make_unique<dem::RveLoading>(model, spec.loading);
    // The last compaction row: where the compaction path continues.
    int last = -1;
    for (std::size_t r = 0; r < db.rows.size(); ++r)
      if (db.rows[r].path == "compaction")
        last = static_cast<int>(r);
    if (last < 0)
      throw std::runtime_error("RVE database: no compaction row to resume");
    std::size_t next_branch      = db.branches.size();
    std::size_t compaction_steps = 0;
    while (bed.relative_density() < spec.final_density * (1.0 - 1e-12))
      {
        double target
          = std::min(bed.relative_density() * std::exp(spec.strain_step),
                     spec.final_density);
        if (next_branch < n_branches)
          target = std::min(target, spec.branch_densities[next_branch]);
        step(*loading,
             bed,
             axial(-std::log(target / bed.relative_density())),
             "compaction");
        last = record(db, -1, "compaction", bed, last);
        ++compaction_steps;
        std::ostringstream line;
        line << "compaction  rho " << bed.relative_density() << "  sigma_zz "
             << db.rows.back().stress[2] / 1e6 << " MPa";
        say(line.str());

        if (next_branch < n_branches
            && bed.relative_density()
                 >= spec.branch_densities[next_branch] * (1.0 - 1e-12))
          {
            const int b = static_cast<int>(next_branch++);
            path_done(-1, "compaction", db, compaction_steps);
            compaction_steps = 0;
            DatabaseBranch br;
            br.relative_density = bed.relative_density();
            br.loaded_stress    = db.rows.back().stress;
            PeriodicBed probe   = bed;

            // Axial unloading until the cell carries no axial stress. The
            // probes start from states of the compaction path: jammed
            // (bonded path: for good) if it has jammed.
            const bool      jammed = loading->jammed(bed);
            dem::RveLoading unloading(model, spec.loading);
            if (jammed)
              unloading.set_jammed();
            int         from = last;
            std::size_t n    = 0;
            for (; n < 200 && db.rows.back().stress[2] < 0.0; ++n)
              {
                step(unloading,
                     probe,
                     axial(0.25 * spec.strain_step),
                     "unloading");
                from = record(db, b, "unloading", probe, from);
              }
            path_done(b, "unloading", db, n);
            const int unloaded  = from;
            br.unloaded_density = probe.relative_density();
            // A fresh calculator per branch: nothing carries over, as in a
            // resumed run.
            dem::TangentCalculator  tangent;
            const dem::CellTangents t = tangent.compute(probe, model);
            br.elastic                = isotropic_projection(
              0.5 * (t.condensed + t.condensed.transpose()));

            br.shear_failure = shear_probe(
              spec, model, probe, db, b, "shear", unloaded, jammed);
            path_done(b, "shear", db, spec.shear_steps);
            PeriodicBed     confined = probe;
            Eigen::Matrix3d v
              = -spec.confinement_strain / 3.0 * Eigen::Matrix3d::Identity();
            step(unloading, confined, v, "confinement");
            const int c = record(db, b, "confinement", confined, unloaded);
            path_done(b, "confinement", db, 1);
            br.confined_shear_failure = shear_probe(
              spec, model, confined, db, b, "confined_shear", c, jammed);
            path_done(b, "confined_shear", db, spec.shear_steps);
            for (const double k : spec.radial_ratios)
              {
                radial_probe(spec, model, bed, db, b, k, last, jammed);
                path_done(b, radial_path_name(k), db, spec.radial_steps);
              }
            db.branches.push_back(br);
            std::ostringstream done;
            done << "branch " << b << "  rho " << br.relative_density << "  E "
                 << br.elastic.youngs_modulus / 1e9 << " GPa  nu "
                 << br.elastic.poisson_ratio << "  shear failure q "
                 << br.shear_failure.q / 1e6 << " / "
                 << br.confined_shear_failure.q / 1e6 << " MPa";
            say(done.str());

            if (control.branch_done)
              control.branch_done(db, bed);
            // Start afresh from this state, as a resumed run does.
            bed.contacts.rebuild(bed.particles, bed.cell, model);
            loading = std::make_unique<dem::RveLoading>(model, spec.loading);
            if (control.stop_after_branches > 0
                && db.branches.size()
                     >= static_cast<std::size_t>(control.stop_after_branches)
                && next_branch < n_branches)
              {
                db.stopped = true;
                say("stopped as asked after branch " + std::to_string(b));
                return db;
              }
          }
      }
    if (compaction_steps > 0)
      path_done(-1, "compaction", db, compaction_steps);
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
                        b.elastic.poisson_ratio,
                        b.relative_density,
                        cap.cap_pressure});
      }
    if (rows.size() < 2)
      return rows;

    // Plastic density at each compaction state: the DPC's elastic
    // volumetric strain there is sum dp / K, K of E, nu interpolated as
    // the DPC table does (linear in density, end rows held).
    auto bulk = [&](const double rho) {
      std::size_t i = 0;
      while (i + 2 < rows.size() && rho > rows[i + 1].relative_density)
        ++i;
      const double w = std::clamp((rho - rows[i].relative_density)
                                    / (rows[i + 1].relative_density
                                       - rows[i].relative_density),
                                  0.0,
                                  1.0);
      const double E
        = (1 - w) * rows[i].youngs_modulus + w * rows[i + 1].youngs_modulus;
      const double nu
        = (1 - w) * rows[i].poisson_ratio + w * rows[i + 1].poisson_ratio;
      return E / (3.0 * (1.0 - 2.0 * nu));
    };
    double      elastic = 0.0, p_old = 0.0, rho_old = 0.0;
    bool        first = true;
    std::size_t next  = 0;
    for (const DatabaseRow &r : db.rows)
      {
        if (r.path != "compaction")
          continue;
        const double p = invariants(r.stress).p;
        if (!first)
          elastic += (p - p_old) / bulk(rho_old);
        first   = false;
        p_old   = p;
        rho_old = r.relative_density;
        while (next < rows.size()
               && r.relative_density
                    >= rows[next].relative_density * (1.0 - 1e-12))
          rows[next++].plastic_density
            = r.relative_density * std::exp(-elastic);
      }
    std::vector<double> rho, rho_p, cap;
    for (const DpcFitRow &r : rows)
      {
        rho.push_back(r.relative_density);
        rho_p.push_back(r.plastic_density);
        cap.push_back(r.fitted_cap_pressure);
      }
    try
      {
        const std::vector<double> y = cap_pressures_at_rows(rho, rho_p, cap);
        for (std::size_t k = 0; k < rows.size(); ++k)
          rows[k].cap_pressure = y[k];
      }
    catch (const std::domain_error &e)
      {
        if (notes)
          notes->push_back(std::string("cap pressures kept at the total "
                                       "density: ")
                           + e.what());
      }
    return rows;
  }
} // namespace compax::coupling
