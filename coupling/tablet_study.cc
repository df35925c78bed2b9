#include "coupling/tablet_study.h"

#include "coupling/rve_material.h"
#include "coupling/tablet_checkpoint.h"
#include "dem/wall_clock.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace compax::coupling
{
  namespace fs = std::filesystem;

  double
  die_wall_pressure(const fem::TabletForces &f)
  {
    return f.die_wall_contact_area > 0.0
             ? f.die_wall_normal_force / f.die_wall_contact_area
             : 0.0;
  }

  void
  TabletSummary::add(const fem::TabletStep &st, const double area)
  {
    const auto &f = st.forces;
    if (st.stage == fem::TabletStage::compaction
        && f.upper_punch_force / area >= max_upper_pressure)
      {
        max_upper_pressure = f.upper_punch_force / area;
        density_at_max     = st.mean_relative_density;
      }
    if (st.stage == fem::TabletStage::unloading)
      {
        density_unloaded = st.mean_relative_density;
        residual_wall    = die_wall_pressure(f);
      }
    if (st.stage == fem::TabletStage::ejection)
      {
        peak_ejection_force
          = std::max(peak_ejection_force, f.lower_punch_force);
        density_out_of_die     = st.mean_relative_density;
        mean_stress_out_of_die = st.mean_stress;
        ejected                = f.die_wall_normal_force == 0.0;
      }
  }

  void
  write_tablet_csv_header(std::ostream &out)
  {
    out << "step,time,stage,upper_punch_displacement,"
           "lower_punch_displacement,upper_punch_pressure,"
           "lower_punch_pressure,die_wall_pressure,ejection_force,"
           "mean_relative_density,upper_punch_force,lower_punch_force,"
           "die_wall_normal_force,die_wall_friction_force,"
           "die_wall_contact_area,sliding_fraction,newton_iterations,"
           "mean_stress\n";
  }

  void
  write_tablet_csv_row(std::ostream          &out,
                       const fem::TabletStep &st,
                       const double           area)
  {
    const auto  &f = st.forces;
    const double ejection_force
      = st.stage == fem::TabletStage::ejection ? f.lower_punch_force : 0.0;
    const auto precision = out.precision(12);
    out << st.index << ',' << st.time << ',' << fem::stage_name(st.stage) << ','
        << st.upper_punch_displacement << ',' << st.lower_punch_displacement
        << ',' << f.upper_punch_force / area << ','
        << f.lower_punch_force / area << ',' << die_wall_pressure(f) << ','
        << ejection_force << ',' << st.mean_relative_density << ','
        << f.upper_punch_force << ',' << f.lower_punch_force << ','
        << f.die_wall_normal_force << ',' << f.die_wall_friction_force << ','
        << f.die_wall_contact_area << ',' << f.sliding_fraction << ','
        << st.newton_iterations << ',' << st.mean_stress << '\n';
    out.precision(precision);
  }

  template <int dim>
  TabletStudy<dim>::TabletStudy(
    const fem::TabletSolverSettings          &settings,
    const fem::TabletProcess                 &process,
    std::shared_ptr<const fem::MaterialModel> material,
    TabletStudyOptions                        options,
    MPI_Comm                                  comm)
      : tablet(settings, material, comm)
      , process(process)
      , material(std::move(material))
      , options(std::move(options))
      , comm(comm)
      , root(dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      , volume0(tablet.volume())
  {
    if (this->options.folder.empty()
        && (this->options.checkpoint_interval > 0
            || !this->options.resume_from.empty()))
      throw std::invalid_argument(
        "a tablet study without output folder cannot checkpoint or resume");
    if (this->options.field_interval == 0)
      throw std::invalid_argument("tablet study: field interval 0");
  }

  template <int dim>
  double
  TabletStudy<dim>::record(const fem::TabletStep &st)
  {
    result.history.push_back(st);
    result.summary.add(st, result.punch_area);
    if (csv.is_open())
      write_tablet_csv_row(csv, st, result.punch_area);
    return die_wall_pressure(st.forces);
  }

  template <int dim>
  void
  TabletStudy<dim>::write_pvd() const
  {
    if (root)
      {
        std::ofstream out(options.folder / "tablet.pvd");
        dealii::DataOutBase::write_pvd_record(out, pvd);
      }
  }

  template <int dim>
  void
  TabletStudy<dim>::write_fields(const fem::TabletStep &st)
  {
    if (!options.write_fields || options.folder.empty())
      return;
    const fem::FieldFiles files = tablet.write_fields(
      options.folder, st.index, st.time, true, options.write_hdf5);
    pvd.emplace_back(st.time, files.vtu_record);
    if (options.write_hdf5)
      {
        xdmf.push_back(files.xdmf);
        fem::write_xdmf_record<dim>(xdmf, options.folder / "tablet.xdmf", comm);
      }
    last_written = st.index;
    write_pvd();
  }

  // The solver state of every rank, the steps so far and the field list,
  // written beside the old checkpoint and swapped in.
  template <int dim>
  void
  TabletStudy<dim>::checkpoint()
  {
    const fs::path fresh = options.folder / "checkpoint.new";
    if (root)
      {
        fs::remove_all(fresh);
        fs::create_directories(fresh);
      }
    MPI_Barrier(comm);
    tablet.save_state(fresh);
    MPI_Barrier(comm);
    if (root)
      {
        TabletCheckpoint c;
        c.steps = result.history;
        std::ostringstream fields;
        fields << std::setprecision(17);
        for (const auto &[time, name] : pvd)
          fields << time << ' ' << name << '\n';
        c.fields = fields.str();
        std::ostringstream            entries;
        boost::archive::text_oarchive archive(entries);
        archive << xdmf;
        c.xdmf = entries.str();
        write_tablet_checkpoint(fresh,
                                options.parameters,
                                dealii::Utilities::MPI::n_mpi_processes(comm),
                                c);
      }
    MPI_Barrier(comm);
    if (root)
      {
        fs::remove_all(options.folder / "checkpoint");
        fs::rename(fresh, options.folder / "checkpoint");
      }
    MPI_Barrier(comm);
  }

  // Reads the checkpoint of options.resume_from, restores the solver from
  // it, copies its field output and replays its steps; returns the step
  // the cycle continues after.
  template <int dim>
  unsigned int
  TabletStudy<dim>::resume()
  {
    const fs::path &old     = options.resume_from;
    const auto      n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    std::vector<fem::TabletStep> done;
    std::string                  error;
    TabletCheckpoint             saved;
    if (root)
      {
        try
          {
            saved = read_tablet_resume(old, options.parameters, n_ranks);
            done  = saved.steps;
            if (done.size() > fem::n_steps(process) + 1)
              throw TabletResumeError(
                "its checkpoint has more steps than this cycle");
          }
        catch (const TabletResumeError &e)
          {
            error = e.what();
          }
      }
    // Every rank throws, or none.
    const auto agree = [&](const std::string &message) {
      if (!message.empty())
        throw TabletResumeError(message);
    };
    agree(dealii::Utilities::MPI::broadcast(comm, error, 0));
    try
      {
        tablet.load_state(old / "checkpoint");
        error.clear();
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    {
      // The first rank's error that failed (a rank that failed alone would
      // leave the others waiting).
      std::string all = error;
      for (unsigned int r = 0; r < n_ranks; ++r)
        {
          const std::string e
            = dealii::Utilities::MPI::broadcast(comm, error, r);
          if (all.empty() && !e.empty())
            all = e;
        }
      agree(all);
    }
    // A checkpoint of the initial state only: start afresh.
    if (done.size() == 1)
      done.clear();
    unsigned int written = 0;
    if (root && !done.empty())
      {
        std::istringstream fields(saved.fields);
        double             time;
        std::string        name;
        while (fields >> time >> name)
          {
            pvd.emplace_back(time, name);
            // tablet_NNNN.pvtu and its pieces tablet_NNNN.<rank>.vtu
            const std::string stem = name.substr(0, name.find('.'));
            written    = std::stoul(stem.substr(stem.find('_') + 1));
            bool found = false;
            for (const auto &e : fs::directory_iterator(old))
              if (e.path().filename().string().rfind(stem + ".", 0) == 0)
                {
                  fs::copy_file(e.path(),
                                options.folder / e.path().filename(),
                                fs::copy_options::overwrite_existing);
                  found = true;
                }
            if (!found)
              error = "the field output " + name
                      + " of its checkpoint is missing in it";
          }
        write_pvd();
        if (options.write_hdf5 && !saved.xdmf.empty())
          {
            std::istringstream            entries(saved.xdmf);
            boost::archive::text_iarchive archive(entries);
            archive >> xdmf;
            fem::write_xdmf_record<dim>(xdmf,
                                        options.folder / "tablet.xdmf",
                                        MPI_COMM_SELF);
          }
      }
    agree(dealii::Utilities::MPI::broadcast(comm, error, 0));
    // Every rank replays the steps: the field output decisions that follow
    // are collective.
    std::uint64_t n_done = done.size();
    MPI_Bcast(&n_done, 1, MPI_UINT64_T, 0, comm);
    done.resize(n_done);
    MPI_Bcast(done.data(),
              static_cast<int>(n_done * sizeof(fem::TabletStep)),
              MPI_BYTE,
              0,
              comm);
    last_written = dealii::Utilities::MPI::broadcast(comm, written, 0);
    for (const auto &st : done)
      record(st);
    if (!result.history.empty())
      {
        last     = result.history.back();
        previous = last.stage;
        if (on_resume)
          on_resume(last);
      }
    return dealii::Utilities::MPI::broadcast(comm, last.index, 0);
  }

  template <int dim>
  std::optional<TabletFe2Report>
  TabletStudy<dim>::fe2_report(const double wall_seconds) const
  {
    const auto *fe2 = dynamic_cast<const RveMaterial *>(material.get());
    if (fe2 == nullptr)
      return std::nullopt;
    const RveMaterialCounters &c     = fe2->counters_so_far();
    const auto                 count = [&](const std::size_t n) {
      return static_cast<unsigned long long>(
        dealii::Utilities::MPI::sum(static_cast<double>(n), comm));
    };
    TabletFe2Report r;
    r.seconds_busiest_rank = dealii::Utilities::MPI::max(c.seconds, comm);
    r.seconds_all_ranks    = dealii::Utilities::MPI::sum(c.seconds, comm);
    r.solves               = count(c.solves);
    r.continuations        = count(c.continuations);
    r.failures             = count(c.failures);
    r.wall_seconds         = wall_seconds;
    r.pool_seconds         = dealii::Utilities::MPI::max(c.pool_seconds, comm);
    r.floor_mean_stress    = dealii::trace(tablet.volume_average(
                            [](dealii::ArrayView<const double> h) {
                              return RveMaterial::floor_stress(h);
                            }))
                          / 3.0;
    return r;
  }

  template <int dim>
  TabletStudyResult
  TabletStudy<dim>::run()
  {
    result                     = {};
    result.punch_area          = tablet.punch_area();
    const unsigned int n_steps = fem::n_steps(process);
    if (root && !options.folder.empty())
      {
        const fs::path file = options.folder / "tablet.csv";
        csv.open(file);
        if (!csv)
          throw std::runtime_error("cannot write '" + file.string() + "'");
        write_tablet_csv_header(csv);
      }
    if (!options.resume_from.empty())
      result.resumed_after = resume();

    const auto start   = std::chrono::steady_clock::now();
    const auto seconds = [&] { return dem::seconds_since(start); };
    const auto step    = [&](const fem::TabletStep &st) {
      // Fields at the end of each stage (the step before a new one) and
      // every field interval.
      if (st.stage != previous && last.index != last_written)
        write_fields(last);
      previous = st.stage;
      last     = st;
      TabletProgress p;
      p.die_wall_pressure = record(st);
      if (on_step)
        {
          p.step    = st;
          p.n_steps = n_steps;
          p.upper_punch_pressure
            = st.forces.upper_punch_force / result.punch_area;
          p.elapsed                    = seconds();
          const unsigned int done_here = st.index - result.resumed_after;
          p.left = done_here > 0 ? p.elapsed * (n_steps - st.index) / done_here
                                    : 0.0;
          on_step(p);
        }
      if (st.index % options.field_interval == 0)
        write_fields(st);
      if (options.checkpoint_interval > 0 && st.index > 0
          && st.index % options.checkpoint_interval == 0)
        checkpoint();
    };
    result.converged = fem::run_tablet_process<dim>(tablet,
                                                    process,
                                                    step,
                                                    result.resumed_after);
    if (last.index != last_written)
      write_fields(last);
    if (!result.converged && options.checkpoint_interval > 0)
      checkpoint();
    result.fe2 = fe2_report(seconds());
    if (csv.is_open())
      csv.close();
    return std::move(result);
  }

  template class TabletStudy<2>;
  template class TabletStudy<3>;
} // namespace compax::coupling
