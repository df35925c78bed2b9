#include "io/csv_writer.h"

#include <iomanip>
#include <stdexcept>

namespace compax::io
{
  CsvWriter::CsvWriter(const std::filesystem::path &file,
                       std::vector<std::string>     columns)
      : out(file)
      , header(std::move(columns))
  {
    if (!out)
      throw std::runtime_error("cannot write '" + file.string() + "'");
    out << std::setprecision(12);
    row << std::setprecision(12);
    for (std::size_t i = 0; i < header.size(); ++i)
      out << (i ? "," : "") << header[i];
    out << '\n';
  }

  void
  CsvWriter::separate()
  {
    if (cells++ > 0)
      row << ',';
  }

  CsvWriter &
  CsvWriter::operator<<(const double value)
  {
    separate();
    row << value;
    return *this;
  }

  CsvWriter &
  CsvWriter::operator<<(const long long value)
  {
    separate();
    row << value;
    return *this;
  }

  CsvWriter &
  CsvWriter::operator<<(const std::string &text)
  {
    separate();
    row << text;
    return *this;
  }

  CsvWriter &
  CsvWriter::empty()
  {
    separate();
    return *this;
  }

  void
  CsvWriter::end_row()
  {
    if (cells != header.size())
      throw std::logic_error("CSV row with " + std::to_string(cells)
                             + " cells for " + std::to_string(header.size())
                             + " columns");
    previous = row.str();
    out << previous << '\n';
    row.str("");
    cells = 0;
  }

  void
  CsvWriter::add_row_text(const std::string &text)
  {
    if (cells != 0)
      throw std::logic_error("CSV row text added inside a row");
    previous = text;
    out << text << '\n';
  }

  void
  CsvWriter::flush()
  {
    out.flush();
  }

  void
  CsvWriter::close()
  {
    out.close();
  }
} // namespace compax::io
