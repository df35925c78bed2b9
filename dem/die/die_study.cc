#include "dem/die/die_study.h"

#include "dem/die/die_setup.h"

#include <ostream>
#include <sstream>
#include <streambuf>
#include <utility>

namespace compax::dem
{
  namespace
  {
    /// Hands each complete line written to it to a callback (without the
    /// newline): DieCompaction formats progress into a stream, the study
    /// reports lines.
    class LineForwarder : public std::streambuf
    {
    public:
      explicit LineForwarder(std::function<void(const std::string &)> to)
          : to(std::move(to))
      {
      }

    protected:
      int
      overflow(const int c) override
      {
        if (c == traits_type::eof())
          return 0;
        if (c == '\n')
          {
            to(line);
            line.clear();
          }
        else
          line += static_cast<char>(c);
        return c;
      }

    private:
      std::function<void(const std::string &)> to;
      std::string                              line;
    };

    /// "particles per material: ..." for beds of two or more materials.
    void
    report_materials(const Bed          &bed,
                     const ContactModel &model,
                     std::ostream       &progress)
    {
      if (model.n_materials() < 2)
        return;
      std::vector<std::size_t> count(model.n_materials(), 0);
      for (const unsigned int m : bed.particles.materials)
        if (m < count.size())
          ++count[m];
      progress << "  particles per material:";
      for (std::size_t a = 0; a < count.size(); ++a)
        progress << (a ? ", " : " ") << count[a] << " of material " << a + 1;
      progress << std::endl;
    }

  } // namespace

  DieTargetError::DieTargetError(const double final_density,
                                 const double packing_density)
      : std::invalid_argument("die study: the final relative density "
                              + std::to_string(final_density)
                              + " must exceed the packing's relative density "
                              + std::to_string(packing_density))
      , packing_density(packing_density)
  {
  }

  std::vector<double>
  die_compaction_targets(const double rho_0,
                         const double final_density,
                         const int    steps)
  {
    if (final_density <= rho_0)
      throw DieTargetError(final_density, rho_0);
    return density_targets(rho_0, final_density, steps);
  }

  DieStudyStart
  DieStudyStart::deposit()
  {
    return {};
  }

  DieStudyStart
  DieStudyStart::resume(Bed bed, DieProgress progress)
  {
    DieStudyStart s;
    s.bed      = std::move(bed);
    s.progress = std::move(progress);
    return s;
  }

  DieStudyStart
  DieStudyStart::branch(Bed bed, const int branch)
  {
    DieStudyStart s;
    s.bed          = std::move(bed);
    s.rerun_branch = branch;
    return s;
  }

  DieStudy::DieStudy(ContactModel    model,
                     DieStudyOptions options,
                     DieStudyStart   start)
      : model_(std::move(model))
      , options_(std::move(options))
      , start_(std::move(start))
  {
    // A resumed run continues the targets of the run it resumes, which
    // started at the density of its first row (the deposit).
    if (start_.progress && !start_.progress->rows.empty())
      options_.protocol.compaction_targets
        = die_compaction_targets(start_.progress->rows.front().relative_density,
                                 options_.final_density,
                                 options_.compaction_steps);
  }

  std::string
  DieStudy::resume_mismatch() const
  {
    if (!start_.progress)
      return {};
    if (!start_.bed)
      return "a resumed die study needs the bed of its checkpoint";
    return DieCompaction(*start_.bed,
                         model_,
                         options_.protocol,
                         options_.equilibrium)
      .resume_mismatch(*start_.progress);
  }

  DieStudyResult
  DieStudy::run(const DieStudyObserver &observer)
  {
    // Progress is formatted only when someone reads it.
    LineForwarder      forwarder(observer.progress);
    std::ostream       lines(&forwarder);
    std::ostream      *progress = observer.progress ? &lines : nullptr;
    std::ostringstream discarded;
    std::ostream      &out = progress ? *progress : discarded;

    DieProtocol protocol = options_.protocol;
    Bed         bed;
    if (start_.bed)
      bed = *start_.bed;
    else
      {
        out << "Packing " << options_.deposition.n_particles
            << " particles by ballistic deposition in a "
            << options_.deposition.die_diameter * 1e3 << " mm die ..."
            << std::endl;
        bed = fill_die(options_.deposition);
        out << "  initial in-die relative density " << bed.relative_density()
            << std::endl;
        protocol.compaction_targets
          = die_compaction_targets(bed.relative_density(),
                                   options_.final_density,
                                   options_.compaction_steps);
      }
    report_materials(bed, model_, out);
    if (protocol.elastic)
      out << "  elastic frictionless spheres, "
          << (protocol.elastic->nonlocal ? "nonlocal contact formulation "
                                           "(Gonzalez & Cuitino 2012)"
                                         : "Hertz contacts")
          << std::endl;

    DieCompaction die(std::move(bed),
                      model_,
                      std::move(protocol),
                      options_.equilibrium);
    die.set_output(nullptr, progress);
    die.on_record       = observer.row;
    die.on_branch_state = observer.branch_state;
    die.on_checkpoint   = observer.checkpoint;

    DieStudyResult result;
    try
      {
        if (start_.rerun_branch > 0)
          die.rerun_branch(start_.rerun_branch);
        else if (start_.progress)
          die.resume(*start_.progress);
        else
          die.run();
        if (start_.rerun_branch == 0 && !die.stopped()
            && options_.protocol.checkpoint_interval > 0 && observer.checkpoint)
          observer.checkpoint(die.bed(), die.progress_state());
      }
    catch (const std::runtime_error &e)
      {
        result.converged      = false;
        result.failure        = die.failed() ? die.failure() : e.what();
        result.last_converged = die.last_converged();
      }
    result.rows       = die.records();
    result.taken_over = start_.progress ? start_.progress->rows.size() : 0;
    result.branches   = die.branches();
    result.pressure_resolution = die.pressure_resolution();
    result.jamming_density     = die.jamming_density();
    result.stopped             = die.stopped();
    result.solver              = die.work;
    result.fits
      = fit_die_study(result.rows, result.branches, result.pressure_resolution);
    return result;
  }
} // namespace compax::dem
