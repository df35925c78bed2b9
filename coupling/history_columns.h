#pragma once

#include "dem/contact/particle_law.h"

#include <cstddef>
#include <vector>

namespace compax::coupling
{
  /**
   * How the archives store a contact's internal variables: its
   * ContactHistory slots, one column each, whatever its law declares them
   * to be. Archives written before the laws declared their variables hold
   * the three columns a_p, a_B, delta_max (or a_p, a_B before delta_max
   * was kept); history_from_columns() reads both.
   */
  inline constexpr std::size_t history_columns = dem::ContactHistory::capacity;

  /// The columns of @p history, appended to @p row.
  void
  append_history(std::vector<double> &row, const dem::ContactHistory &history);

  /**
   * The history of a contact of law @p law saved in the @p n_columns
   * values at @p columns: the slots themselves when n_columns is
   * history_columns, else the legacy columns (a_p, a_B[, delta_max]) put
   * into the slots whose declared names they carry. Throws
   * std::runtime_error for another number of columns.
   */
  dem::ContactHistory
  history_from_columns(const double           *columns,
                       std::size_t             n_columns,
                       const dem::ParticleLaw &law);
} // namespace compax::coupling
