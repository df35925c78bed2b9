#pragma once

#include <deal.II/base/array_view.h>

#include <cstddef>
#include <istream>
#include <ostream>
#include <vector>

namespace compax::fem
{
  /**
   * Committed and trial history values of many material (or contact)
   * points, n_values each, in two flat arrays allocated once. Trial
   * evaluations write only the trial array; commit() copies it over the
   * committed one after a converged load increment, and a cut increment
   * simply never commits, so the committed state is never touched by an
   * iteration that is thrown away.
   */
  class QuadratureHistory
  {
  public:
    void
    reinit(const std::size_t n_points, const unsigned int n_values_per_point)
    {
      n_values = n_values_per_point;
      committed_values.assign(n_points * n_values, 0.0);
      trial_values.assign(n_points * n_values, 0.0);
    }

    std::size_t
    n_points() const
    {
      return n_values == 0 ? 0 : committed_values.size() / n_values;
    }

    dealii::ArrayView<const double>
    committed(const std::size_t point) const
    {
      return {committed_values.data() + point * n_values, n_values};
    }

    /// Writable committed state, for initialisation and rotation at commit.
    dealii::ArrayView<double>
    committed(const std::size_t point)
    {
      return {committed_values.data() + point * n_values, n_values};
    }

    dealii::ArrayView<double>
    trial(const std::size_t point)
    {
      return {trial_values.data() + point * n_values, n_values};
    }

    dealii::ArrayView<const double>
    trial(const std::size_t point) const
    {
      return {trial_values.data() + point * n_values, n_values};
    }

    /// Accepts the trial state of every point.
    void
    commit()
    {
      committed_values = trial_values;
    }

    /// Makes the trial state equal to the committed one.
    void
    revert()
    {
      trial_values = committed_values;
    }

    /// Writes the committed state (for checkpoints).
    void
    save(std::ostream &out) const
    {
      const std::size_t n = committed_values.size();
      out.write(reinterpret_cast<const char *>(&n_values), sizeof(n_values));
      out.write(reinterpret_cast<const char *>(&n), sizeof(n));
      out.write(reinterpret_cast<const char *>(committed_values.data()),
                n * sizeof(double));
    }

    /// Reads a state written by save() into a store of the same layout;
    /// returns false (and changes nothing) if the layout differs.
    bool
    load(std::istream &in)
    {
      unsigned int nv = 0;
      std::size_t  n  = 0;
      in.read(reinterpret_cast<char *>(&nv), sizeof(nv));
      in.read(reinterpret_cast<char *>(&n), sizeof(n));
      if (!in || nv != n_values || n != committed_values.size())
        return false;
      in.read(reinterpret_cast<char *>(committed_values.data()),
              n * sizeof(double));
      trial_values = committed_values;
      return static_cast<bool>(in);
    }

  private:
    unsigned int        n_values = 0;
    std::vector<double> committed_values;
    std::vector<double> trial_values;
  };
} // namespace compax::fem
