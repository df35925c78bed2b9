#pragma once

#include <array>
#include <cstddef>

/**
 * @file
 * The internal variables a contact keeps between converged states, in the
 * slots its law declares: the history of a contact is a short, fixed array
 * so that contact lists stay contiguous whatever law each contact holds,
 * and the meaning of each slot belongs to the law (as a pair style of an
 * explicit-DEM code registers its own history values).
 */

namespace compax::dem
{
  /// One internal variable a contact law declares: its symbol (the CSV
  /// column of `compax contact`, "a_p"), its name (VTU arrays and
  /// archives, "plastic_radius") and its unit.
  struct HistoryVariable
  {
    const char *symbol;
    const char *name;
    const char *unit;
  };

  /**
   * Internal variables of one contact, slot k holding the law's k-th
   * declared HistoryVariable; unused slots stay 0. They change only
   * through a law's updated_history(), called on converged states, never
   * during trial evaluations.
   */
  struct ContactHistory
  {
    /// Slots of every contact: the most any registered law declares.
    static constexpr std::size_t capacity = 2;

    std::array<double, capacity> values{};

    double
    operator[](const std::size_t slot) const
    {
      return values[slot];
    }

    double &
    operator[](const std::size_t slot)
    {
      return values[slot];
    }

    bool
    operator==(const ContactHistory &other) const
    {
      return values == other.values;
    }
  };

  /// Whether a contact keeps internal variables: any slot is non-zero.
  inline bool
  has_history(const ContactHistory &h)
  {
    for (const double v : h.values)
      if (v != 0.0)
        return true;
    return false;
  }
} // namespace compax::dem
