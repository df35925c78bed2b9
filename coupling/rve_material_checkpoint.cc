// Checkpoint of the FE2 material's own state (RveMaterial::save_state and
// load_state): the RVEs of the rank's material points, which live in the
// material, not in the quadrature histories.
#include "coupling/hdf5_archive.h"
#include "coupling/rve_archive.h"
#include "coupling/rve_material.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace compax::coupling
{
  namespace
  {
    std::filesystem::path
    state_file(const std::filesystem::path &folder, const unsigned int rank)
    {
      return folder / ("rve." + std::to_string(rank) + ".h5");
    }

    /**
     * Rebuilds the contact list of every cell that holds particles at its
     * current state, as load_rve() does to a loaded cell, so that the
     * running material continues from exactly the state a resumed one
     * loads (as `compax rve` refreshes its cell at a checkpoint). Returns
     * per cell 1 (saved), 0 (empty: a point owns no cell until it jams) or,
     * with @p tolerate_failures, 2 for a cell whose list cannot be rebuilt
     * (thinner than its particles plus the skin); otherwise that throws.
     */
    std::vector<double>
    refresh(std::vector<dem::PeriodicBed> &cells,
            const dem::ContactModel       &model,
            const std::string             &name,
            const bool                     tolerate_failures)
    {
      std::vector<double> flags(cells.size(), 0.0);
      for (std::size_t k = 0; k < cells.size(); ++k)
        {
          dem::PeriodicBed &cell = cells[k];
          if (cell.particles.size() == 0)
            continue;
          try
            {
              cell.contacts.rebuild(cell.particles, cell.cell, model);
              flags[k] = 1.0;
            }
          catch (const std::runtime_error &e)
            {
              if (!tolerate_failures)
                throw std::runtime_error("multiscale-fe2: cannot checkpoint "
                                         + name + " RVE " + std::to_string(k)
                                         + ": " + e.what());
              flags[k] = 2.0;
            }
        }
      return flags;
    }

    void
    save_cells(Hdf5ArchiveWriter                   &archive,
               const std::string                   &name,
               const std::vector<dem::PeriodicBed> &cells,
               const std::vector<double>           &flags)
    {
      archive.write_array(name + "_present", flags);
      for (std::size_t k = 0; k < cells.size(); ++k)
        if (flags[k] == 1.0)
          save_rve(archive, name + "/" + std::to_string(k), cells[k]);
    }

    std::vector<dem::PeriodicBed>
    load_cells(const Hdf5ArchiveReader &archive,
               const std::string       &name,
               const std::size_t        count,
               const dem::ContactModel &model)
    {
      const std::vector<double> flags = archive.read_array(name + "_present");
      if (flags.size() != count)
        throw std::runtime_error("'" + name + "_present' holds "
                                 + std::to_string(flags.size())
                                 + " flags, expected " + std::to_string(count));
      std::vector<dem::PeriodicBed> cells(count);
      for (std::size_t k = 0; k < count; ++k)
        if (flags[k] == 1.0)
          cells[k] = load_rve(archive, name + "/" + std::to_string(k), model);
      return cells;
    }
  } // namespace

  void
  RveMaterial::save_state(const std::filesystem::path &folder,
                          const unsigned int           rank) const
  {
    // The committed cell, the trial cell (after a commit it is the newest
    // committed state, promoted at the next evaluation: see catch_up) and
    // the committed counter of every point, so that the resumed points
    // continue exactly as the running ones do; and the pool, so that
    // points that have not jammed yet switch to the same packings.
    //
    // A trial cell whose list cannot be rebuilt is the leftover of a failed
    // trial (a cell squeezed thinner than its particles: no equilibrium
    // solve that needs a new list gets through it), not a state a
    // resumed point continues from; it is not saved and loads empty.
    const std::vector<double> pool_flags
      = refresh(templates, model, "pool", false);
    const std::vector<double> committed_flags
      = refresh(committed, model, "committed", false);
    const std::vector<double> trial_flags
      = refresh(trial, model, "trial", true);
    Hdf5ArchiveWriter archive(state_file(folder, rank).string(),
                              {archive_kind::fe2_rve_states,
                               spec.checkpoint_parameters});
    archive.write_attribute("points", static_cast<double>(committed.size()));
    archive.write_attribute("template_density", template_density);
    archive.write_array("committed_steps", committed_steps);
    archive.write_array("template_jamming_density", template_jamming_density);
    archive.write_array("template_modulus", template_modulus);
    save_cells(archive, "templates", templates, pool_flags);
    save_cells(archive, "committed", committed, committed_flags);
    save_cells(archive, "trial", trial, trial_flags);
    archive.commit();
  }

  void
  RveMaterial::load_state(const std::filesystem::path &folder,
                          const unsigned int           rank) const
  {
    const std::filesystem::path path = state_file(folder, rank);
    const std::string what = "multiscale-fe2 RVE checkpoint " + path.string();
    if (!std::filesystem::is_regular_file(path))
      throw std::runtime_error(what
                               + ": missing (the checkpoint was not "
                                 "written by a multiscale-fe2 run)");
    const std::size_t             n = committed.size();
    std::vector<dem::PeriodicBed> new_templates, new_committed, new_trial;
    std::vector<double>           jamming, modulus, steps;
    double                        density = -1.0;
    std::string                   error;
    {
      try
        {
          const Hdf5ArchiveReader archive(path.string(),
                                          archive_kind::fe2_rve_states,
                                          spec.checkpoint_parameters);
          const double            points = archive.read_attribute("points");
          if (points != static_cast<double>(n))
            throw std::runtime_error(
              "holds the RVEs of " + std::to_string(std::llround(points))
              + " material points, this run has " + std::to_string(n)
              + " on MPI rank " + std::to_string(rank)
              + " (another mesh, partition or material?)");
          steps = archive.read_array("committed_steps");
          if (steps.size() != n)
            throw std::runtime_error(
              "'committed_steps' holds " + std::to_string(steps.size())
              + " values, expected " + std::to_string(n));
          density = archive.read_attribute("template_density");
          jamming = archive.read_array("template_jamming_density");
          modulus = archive.read_array("template_modulus");
          if (jamming.empty() || modulus.size() != jamming.size())
            throw std::runtime_error("malformed RVE pool");
          // This run's pool (built when its points were initialized) must
          // be the checkpoint's: the same parameters draw the same
          // packings, other ones would switch the remaining points to
          // other cells.
          if (!templates.empty())
            {
              bool same = templates.size() == jamming.size();
              for (std::size_t k = 0; same && k < jamming.size(); ++k)
                same = std::abs(template_jamming_density[k] - jamming[k])
                       <= 1e-9 * jamming[k];
              if (!same)
                throw std::runtime_error(
                  "its RVE pool differs from this run's (other Multiscale "
                  "parameters?)");
            }
          new_templates
            = load_cells(archive, "templates", jamming.size(), model);
          for (const dem::PeriodicBed &cell : new_templates)
            if (cell.particles.size() == 0)
              throw std::runtime_error("empty RVE in the pool");
          new_committed = load_cells(archive, "committed", n, model);
          new_trial     = load_cells(archive, "trial", n, model);
        }
      catch (const Hdf5ArchiveError &e)
        {
          error = e.reason();
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    }
    if (!error.empty())
      throw std::runtime_error(what + ": " + error);
    templates                = std::move(new_templates);
    template_jamming_density = std::move(jamming);
    template_modulus         = std::move(modulus);
    template_density         = density;
    committed                = std::move(new_committed);
    trial                    = std::move(new_trial);
    committed_steps          = std::move(steps);
  }
} // namespace compax::coupling
