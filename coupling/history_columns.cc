#include "coupling/history_columns.h"

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

namespace compax::coupling
{
  void
  append_history(std::vector<double> &row, const dem::ContactHistory &history)
  {
    row.insert(row.end(), history.values.begin(), history.values.end());
  }

  dem::ContactHistory
  history_from_columns(const double           *columns,
                       const std::size_t       n_columns,
                       const dem::ParticleLaw &law)
  {
    dem::ContactHistory history;
    if (n_columns == history_columns)
      {
        std::copy(columns, columns + n_columns, history.values.begin());
        return history;
      }
    // The variables of the legacy columns, by the names the laws declare.
    // Told apart from the slots by their number: a capacity of 3 would
    // need a new archive format version instead.
    static_assert(history_columns != 3);
    constexpr std::array<const char *, 3> legacy_names{"plastic_radius",
                                                       "bond_radius",
                                                       "largest_overlap"};
    if (n_columns != legacy_names.size())
      throw std::runtime_error("archive holds " + std::to_string(n_columns)
                               + " internal variables per contact; expected "
                               + std::to_string(history_columns)
                               + " (or 3 in older archives)");
    const std::vector<dem::HistoryVariable> declared
      = dem::history_variables(law);
    for (std::size_t slot = 0; slot < declared.size(); ++slot)
      for (std::size_t c = 0; c < legacy_names.size(); ++c)
        if (std::strcmp(declared[slot].name, legacy_names[c]) == 0)
          history[slot] = columns[c];
    return history;
  }
} // namespace compax::coupling
