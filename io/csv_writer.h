#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace compax::io
{
  /**
   * A CSV table with a fixed header, written row by row as a study
   * computes it (a killed run keeps the rows so far; CsvTable holds a
   * whole table, for reading). Numbers are written with 12 significant
   * digits, as CsvTable writes them, enough for plots and for tests that
   * re-derive physics from the file; text cells are written as they are.
   */
  class CsvWriter
  {
  public:
    CsvWriter(const std::filesystem::path &file,
              std::vector<std::string>     columns);

    /// Appends one cell of the current row.
    CsvWriter &
    operator<<(double value);
    CsvWriter &
    operator<<(long long value);
    CsvWriter &
    operator<<(int value)
    {
      return *this << static_cast<long long>(value);
    }
    CsvWriter &
    operator<<(const std::string &text);

    /// An empty cell (a quantity that does not apply).
    CsvWriter &
    empty();

    /// Ends the current row; throws if it does not have one cell per column.
    void
    end_row();

    /// The text of the row ended last (without the line break).
    const std::string &
    last_row() const
    {
      return previous;
    }

    /// Appends a row given as its text (e.g. one ended by another writer
    /// with the same columns).
    void
    add_row_text(const std::string &text);

    /// Writes what is buffered to the file.
    void
    flush();

    /// Flushes and closes the file, e.g. before a plot reads it.
    void
    close();

  private:
    void
    separate();

    std::ofstream            out;
    std::ostringstream       row;
    std::string              previous;
    std::vector<std::string> header;
    std::size_t              cells = 0;
  };
} // namespace compax::io
