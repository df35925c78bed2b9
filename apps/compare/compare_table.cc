#include "apps/compare/compare_table.h"

#include "apps/common/csv_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace compax::cli
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  }

  double
  interpolate(const DensitySeries &s, const double x, const double reach)
  {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    if (n == 0 || !std::isfinite(x))
      return nan;
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) {
      return s.x[a] < s.x[b];
    });
    const double lo = s.x[order.front()], hi = s.x[order.back()];
    if (x < lo - reach || x > hi + reach)
      return nan;
    if (x < lo || x > hi)
      {
        // Within reach of an end: extend the end segment.
        if (n == 1 || lo == hi)
          return s.y[order.front()];
        const std::size_t a = x < lo ? order[0] : order[n - 2];
        const std::size_t b = x < lo ? order[1] : order[n - 1];
        return s.y[a] + (s.y[b] - s.y[a]) * (x - s.x[a]) / (s.x[b] - s.x[a]);
      }
    for (std::size_t k = 0; k < n; ++k)
      if (s.x[order[k]] == x)
        return s.y[order[k]];
    for (std::size_t k = 1; k < n; ++k)
      {
        const double x0 = s.x[order[k - 1]], x1 = s.x[order[k]];
        if (x0 < x && x < x1)
          {
            const double y0 = s.y[order[k - 1]], y1 = s.y[order[k]];
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
          }
      }
    return nan;
  }

  double
  ComparisonRow::relative_difference() const
  {
    if (!std::isfinite(value) || !std::isfinite(reference) || reference == 0.0)
      return nan;
    return (value - reference) / std::abs(reference);
  }

  std::vector<ComparisonRow>
  compare_series(const std::string   &comparison,
                 const DensitySeries &reference,
                 const DensitySeries &compared,
                 const double         reach)
  {
    std::vector<ComparisonRow> rows;
    const std::size_t n = std::min(reference.x.size(), reference.y.size());
    for (std::size_t k = 0; k < n; ++k)
      if (std::isfinite(reference.y[k]) && reference.y[k] != 0.0
          && std::isfinite(reference.x[k]))
        rows.push_back({comparison,
                        reference.x[k],
                        reference.y[k],
                        interpolate(compared, reference.x[k], reach)});
    return rows;
  }

  const std::vector<std::string> &
  comparison_columns()
  {
    static const std::vector<std::string> names = {"comparison",
                                                   "relative_density",
                                                   "reference",
                                                   "value",
                                                   "relative_difference"};
    return names;
  }

  void
  write_comparison_csv(const std::filesystem::path      &file,
                       const std::vector<ComparisonRow> &rows)
  {
    CsvWriter csv(file, comparison_columns());
    for (const ComparisonRow &r : rows)
      {
        csv << r.comparison << r.relative_density << r.reference;
        if (std::isfinite(r.value))
          csv << r.value << r.relative_difference();
        else
          csv.empty().empty();
        csv.end_row();
      }
    csv.close();
  }

  CsvTable::CsvTable(const std::filesystem::path &file_)
      : file(file_)
  {
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("cannot read " + file.string());
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    {
      std::stringstream names(line);
      for (std::string name; std::getline(names, name, ',');)
        header.push_back(name);
    }
    for (const std::string &name : header)
      cells[name];
    while (std::getline(in, line))
      {
        if (line.empty())
          continue;
        std::stringstream row(line);
        for (const std::string &name : header)
          {
            std::string cell;
            std::getline(row, cell, ',');
            cells[name].push_back(cell);
          }
        ++n_rows;
      }
  }

  bool
  CsvTable::has(const std::string &column) const
  {
    return cells.count(column) > 0;
  }

  const std::vector<std::string> &
  CsvTable::text(const std::string &column) const
  {
    const auto it = cells.find(column);
    if (it == cells.end())
      throw std::runtime_error(file.string() + " has no column '" + column
                               + "'");
    return it->second;
  }

  std::vector<double>
  CsvTable::numbers(const std::string &column) const
  {
    std::vector<double> v;
    for (const std::string &cell : text(column))
      {
        char        *end   = nullptr;
        const double value = std::strtod(cell.c_str(), &end);
        v.push_back(!cell.empty() && end == cell.c_str() + cell.size() ? value
                                                                       : nan);
      }
    return v;
  }
} // namespace compax::cli
