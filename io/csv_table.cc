#include "io/csv_table.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace compax::io
{
  namespace
  {
    std::string
    trim(const std::string &text)
    {
      const auto begin = text.find_first_not_of(" \t\r");
      if (begin == std::string::npos)
        return {};
      return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
    }

    /// The cells of a line, trimmed ("a,,b" has an empty middle cell).
    std::vector<std::string>
    split(const std::string &line)
    {
      std::vector<std::string> cells;
      std::size_t              start = 0;
      for (std::size_t comma; (comma = line.find(',', start)) != line.npos;
           start = comma + 1)
        cells.push_back(trim(line.substr(start, comma - start)));
      cells.push_back(trim(line.substr(start)));
      return cells;
    }

    std::string
    line_text(const std::size_t line)
    {
      return "line " + std::to_string(line);
    }
  } // namespace

  CsvError::CsvError(const std::string &file, const std::string &reason)
      : FileError("CSV file", file, reason)
  {
  }

  CsvTable::CsvTable(std::vector<std::string> columns)
      : names(std::move(columns))
  {
  }

  CsvTable
  CsvTable::read(const std::filesystem::path &file)
  {
    std::ifstream in(file);
    if (!in)
      throw CsvError(file.string(), "cannot be opened");
    return read(in, file.string());
  }

  CsvTable
  CsvTable::read(std::istream &in, const std::string &name)
  {
    CsvTable    table;
    bool        header = true;
    std::size_t number = 0;
    table.source       = name;
    for (std::string line; std::getline(in, line);)
      {
        ++number;
        const std::string trimmed = trim(line);
        if (trimmed.empty() || trimmed.front() == '#')
          continue;
        std::vector<std::string> cells = split(trimmed);
        if (header)
          {
            for (std::size_t c = 0; c < cells.size(); ++c)
              {
                if (cells[c].empty())
                  throw CsvError(name,
                                 line_text(number)
                                   + ": the header has an empty column name");
                if (std::find(cells.begin(), cells.begin() + c, cells[c])
                    != cells.begin() + c)
                  throw CsvError(name,
                                 line_text(number) + ": column '" + cells[c]
                                   + "' appears twice in the header");
              }
            table.names       = std::move(cells);
            table.header_line = number;
            header            = false;
            continue;
          }
        if (cells.size() != table.names.size())
          throw CsvError(name,
                         line_text(number) + ": expected "
                           + std::to_string(table.names.size())
                           + " cells (one per column of the header), found "
                           + std::to_string(cells.size()));
        table.cells.push_back(std::move(cells));
        table.lines.push_back(number);
      }
    if (header)
      throw CsvError(name, "has no header line");
    return table;
  }

  void
  CsvTable::write(const std::filesystem::path &file) const
  {
    std::ofstream out(file);
    if (!out)
      throw CsvError(file.string(), "cannot be written");
    write(out);
    if (!out.flush())
      throw CsvError(file.string(), "cannot be written");
  }

  void
  CsvTable::write(std::ostream &out) const
  {
    const auto line = [&out](const std::vector<std::string> &cells) {
      for (std::size_t c = 0; c < cells.size(); ++c)
        out << (c ? "," : "") << cells[c];
      out << '\n';
    };
    line(names);
    for (const auto &row : cells)
      line(row);
  }

  void
  CsvTable::add_row(std::vector<std::string> row)
  {
    if (row.size() != names.size())
      throw std::invalid_argument("CSV row with " + std::to_string(row.size())
                                  + " cells for " + std::to_string(names.size())
                                  + " columns");
    cells.push_back(std::move(row));
    lines.push_back(header_line + cells.size());
  }

  void
  CsvTable::add_row(const std::vector<double> &values)
  {
    std::vector<std::string> row;
    for (const double v : values)
      {
        std::ostringstream cell;
        cell << std::setprecision(12) << v;
        row.push_back(cell.str());
      }
    add_row(std::move(row));
  }

  bool
  CsvTable::has(const std::string &name) const
  {
    return std::find(names.begin(), names.end(), name) != names.end();
  }

  std::size_t
  CsvTable::column(const std::string &name) const
  {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw CsvError(source,
                     line_text(header_line) + ": the header has no column '"
                       + name + "'");
    return it - names.begin();
  }

  std::string
  CsvTable::where(const std::size_t row, const std::size_t column) const
  {
    return line_text(lines.at(row)) + ", column '" + names.at(column) + "'";
  }

  double
  CsvTable::number(const std::size_t row, const std::size_t column) const
  {
    const std::string &cell = text(row, column);
    char              *end  = nullptr;
    const double       v    = std::strtod(cell.c_str(), &end);
    if (cell.empty())
      throw CsvError(source,
                     where(row, column) + ": empty cell, expected a number");
    if (end != cell.c_str() + cell.size())
      throw CsvError(source,
                     where(row, column) + ": '" + cell + "' is not a number");
    return v;
  }

  std::vector<double>
  CsvTable::numbers(const std::string &name) const
  {
    const std::size_t   c = column(name);
    std::vector<double> values;
    for (std::size_t r = 0; r < rows(); ++r)
      values.push_back(number(r, c));
    return values;
  }
} // namespace compax::io
