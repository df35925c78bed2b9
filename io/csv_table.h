#pragma once

#include "io/file_error.h"

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace compax::io
{
  /**
   * A CSV file that cannot be read as asked. what() names the file and,
   * where there is one, the line and the column; reason() is the same
   * without the file, for messages that name the file themselves (an
   * input entry and its value).
   */
  class CsvError : public FileError
  {
  public:
    CsvError(const std::string &file, const std::string &reason);
  };

  /**
   * A CSV table: a header line of column names and rows of cells, the form
   * of every CSV file compax writes and reads (one type, so that every
   * reader refuses bad input alike: with the file, line and column).
   *
   * Reading skips blank lines and lines starting with '#' (comments, also
   * before the header), trims blanks around cells and refuses a header
   * with an empty or repeated name and a row whose cell count differs from
   * the header's. Cells stay text until a column is asked for as numbers.
   * Writing gives numbers 12 significant digits, as compax's outputs.
   */
  class CsvTable
  {
  public:
    /// An empty table with these columns (for writing).
    explicit CsvTable(std::vector<std::string> columns = {});

    /// Reads @p file; throws CsvError if it cannot be opened, has no
    /// header or a malformed line.
    static CsvTable
    read(const std::filesystem::path &file);

    /// Reads a table from @p in; @p name stands for the file in errors.
    static CsvTable
    read(std::istream &in, const std::string &name);

    /// Writes the header and the rows; throws CsvError if @p file cannot
    /// be written.
    void
    write(const std::filesystem::path &file) const;

    void
    write(std::ostream &out) const;

    /// Appends a row of text cells; throws std::invalid_argument unless it
    /// has one cell per column.
    void
    add_row(std::vector<std::string> cells);

    /// Appends a row of numbers (12 significant digits; NaN as "nan").
    void
    add_row(const std::vector<double> &values);

    const std::vector<std::string> &
    columns() const
    {
      return names;
    }

    std::size_t
    rows() const
    {
      return cells.size();
    }

    bool
    has(const std::string &column) const;

    /// The index of @p column; throws CsvError naming the header line and
    /// the column if the header has no such column.
    std::size_t
    column(const std::string &name) const;

    /// The text of a cell.
    const std::string &
    text(std::size_t row, std::size_t column) const
    {
      return cells.at(row).at(column);
    }

    /**
     * A cell as a number: the whole cell must be one (strtod; "nan" and
     * "inf", as compax writes them, are numbers: the caller decides
     * whether they are allowed). Throws CsvError naming the line and the
     * column otherwise.
     */
    double
    number(std::size_t row, std::size_t column) const;

    /// Every cell of @p column as a number (number()); throws CsvError for
    /// a missing column or a cell that is not a number.
    std::vector<double>
    numbers(const std::string &column) const;

    /// "line <n>, column '<name>'" of a cell, for a caller's own refusal
    /// of a value (out of range, not finite).
    std::string
    where(std::size_t row, std::size_t column) const;

    /// The file the table was read from (empty if built in memory).
    const std::string &
    file() const
    {
      return source;
    }

  private:
    std::string                           source;
    std::vector<std::string>              names;
    std::size_t                           header_line = 1;
    std::vector<std::vector<std::string>> cells;
    /// The line in the file of each row.
    std::vector<std::size_t> lines;
  };
} // namespace compax::io
