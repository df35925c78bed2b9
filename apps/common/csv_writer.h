#pragma once

#include "io/csv_writer.h"

namespace compax::cli
{
  /// For apps/compare until it is ported to io::CsvWriter and io::CsvTable.
  using io::CsvWriter;
} // namespace compax::cli
