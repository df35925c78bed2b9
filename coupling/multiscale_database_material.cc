#include "coupling/multiscale_database_material.h"

#include <deal.II/base/mpi.h>

#include <exception>
#include <stdexcept>
#include <vector>

namespace compax::coupling
{
  namespace
  {
    /// The fitted rows as a flat list of numbers (to broadcast) and back.
    std::vector<double>
    to_numbers(const std::vector<DpcFitRow> &rows)
    {
      std::vector<double> numbers;
      for (const DpcFitRow &r : rows)
        numbers.insert(numbers.end(),
                       {r.relative_density,
                        r.cohesion,
                        r.friction_angle_deg,
                        r.cap_eccentricity,
                        r.cap_pressure,
                        r.youngs_modulus,
                        r.poisson_ratio,
                        r.plastic_density,
                        r.fitted_cap_pressure});
      return numbers;
    }

    std::vector<DpcFitRow>
    to_rows(const std::vector<double> &numbers)
    {
      std::vector<DpcFitRow> rows;
      for (std::size_t k = 0; k + 9 <= numbers.size(); k += 9)
        {
          const double *v = &numbers[k];
          rows.push_back(
            {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]});
        }
      return rows;
    }
  } // namespace

  std::shared_ptr<fem::DruckerPragerCap>
  make_multiscale_database_material(const DatabaseSpec               &spec,
                                    const dem::ContactModel          &model,
                                    MPI_Comm                          comm,
                                    const MultiscaleDatabaseObserver &observer)
  {
    // Whatever goes wrong on rank 0 reaches every rank (which would
    // otherwise wait for the table forever) as the same kind of error:
    // std::runtime_error (e.g. an RVE that did not converge) or another.
    std::exception_ptr     error;
    std::string            message;
    int                    runtime_error = 0;
    std::vector<DpcFitRow> fit;
    const bool builder = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    if (builder)
      try
        {
          if (observer.started)
            observer.started();
          RveDatabaseStudyOptions options;
          options.spec     = spec;
          options.validate = false;
          RveDatabaseStudy study(model, options);
          study.on_progress                   = observer.progress;
          const RveDatabaseStudyResult result = study.run();
          if (result.outcome == RveDatabaseOutcome::database_failed)
            throw std::runtime_error(result.failure);
          if (observer.built)
            observer.built(result);
          fit = result.fit;
        }
      catch (const std::exception &e)
        {
          error   = std::current_exception();
          message = e.what();
          if (message.empty())
            message = "the RVE database failed";
          runtime_error
            = dynamic_cast<const std::runtime_error *>(&e) != nullptr;
        }
    message       = dealii::Utilities::MPI::broadcast(comm, message, 0);
    runtime_error = dealii::Utilities::MPI::broadcast(comm, runtime_error, 0);
    if (error)
      std::rethrow_exception(error);
    if (!message.empty())
      {
        if (runtime_error)
          throw std::runtime_error(message);
        throw std::logic_error(message);
      }
    fit = to_rows(dealii::Utilities::MPI::broadcast(comm, to_numbers(fit), 0));
    return std::make_shared<fem::DruckerPragerCap>(to_dpc_table(fit));
  }
} // namespace compax::coupling
