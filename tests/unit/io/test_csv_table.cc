// The CSV table every reader shares: what it writes reads back equal, and
// bad input is refused with the file, the line and the column.
#include "io/csv_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <unistd.h>

using compax::io::CsvError;
using compax::io::CsvTable;

namespace
{
  /// The message of the CsvError that @p read throws.
  template <typename Read>
  std::string
  refusal(Read &&read)
  {
    try
      {
        read();
      }
    catch (const CsvError &e)
      {
        return e.what();
      }
    ADD_FAILURE() << "no CsvError";
    return {};
  }

  CsvTable
  parse(const std::string &text)
  {
    std::istringstream in(text);
    return CsvTable::read(in, "t.csv");
  }
} // namespace

TEST(CsvTable, WrittenTableReadsBackEqual)
{
  CsvTable table({"stage", "relative_density", "pressure"});
  table.add_row({"compaction", "0.5", "1e6"});
  table.add_row(std::vector<double>{1.0, 0.123456789012345, -2.5e-7});
  table.add_row(std::vector<double>{2.0, std::nan(""), 3.0});
  const auto file = std::filesystem::temp_directory_path()
                    / ("compax-csv-" + std::to_string(::getpid()) + ".csv");
  table.write(file);
  const CsvTable back = CsvTable::read(file);
  std::filesystem::remove(file);

  EXPECT_EQ(back.columns(), table.columns());
  ASSERT_EQ(back.rows(), table.rows());
  for (std::size_t r = 0; r < table.rows(); ++r)
    for (std::size_t c = 0; c < table.columns().size(); ++c)
      EXPECT_EQ(back.text(r, c), table.text(r, c));
  EXPECT_EQ(back.numbers("pressure")[0], 1e6);
  EXPECT_EQ(back.numbers("relative_density")[1], 0.123456789012);
  EXPECT_TRUE(std::isnan(back.numbers("relative_density")[2]));
  EXPECT_EQ(back.text(0, back.column("stage")), "compaction");
}

TEST(CsvTable, CommentsBlankLinesAndBlanksAroundCellsAreSkipped)
{
  const CsvTable t = parse("# a comment\n\n a , b\n1, 2\n  \n# more\n3 ,4\n");
  EXPECT_EQ(t.columns(), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(t.numbers("b"), (std::vector<double>{2.0, 4.0}));
  EXPECT_EQ(t.where(1, 0), "line 7, column 'a'");
}

TEST(CsvTable, MissingColumnIsRefusedNamingFileLineAndColumn)
{
  const CsvTable t = parse("# header next\nx,y\n1,2\n");
  EXPECT_FALSE(t.has("z"));
  const std::string what = refusal([&] { t.numbers("z"); });
  EXPECT_NE(what.find("'t.csv'"), std::string::npos) << what;
  EXPECT_NE(what.find("line 2"), std::string::npos) << what;
  EXPECT_NE(what.find("'z'"), std::string::npos) << what;
}

TEST(CsvTable, NonNumericCellIsRefusedNamingFileLineAndColumn)
{
  const CsvTable    t    = parse("x,y\n1,2\n3,4.5abc\n");
  const std::string what = refusal([&] { t.numbers("y"); });
  EXPECT_EQ(what,
            "CSV file 't.csv': line 3, column 'y': '4.5abc' is not a number");
  const CsvTable empty = parse("x,y\n1,\n");
  EXPECT_NE(refusal([&] {
              empty.numbers("y");
            }).find("line 2, column 'y': empty cell"),
            std::string::npos);
}

TEST(CsvTable, MalformedFilesAreRefused)
{
  EXPECT_NE(refusal([] { parse("x,y\n1,2,3\n"); })
              .find("line 2: expected 2 cells (one per column of the "
                    "header), found 3"),
            std::string::npos);
  EXPECT_NE(refusal([] { parse("x,x\n"); }).find("'x' appears twice"),
            std::string::npos);
  EXPECT_NE(refusal([] { parse("# only a comment\n"); }).find("no header"),
            std::string::npos);
  EXPECT_NE(refusal([] {
              CsvTable::read("/nonexistent/compax.csv");
            }).find("'/nonexistent/compax.csv': cannot be opened"),
            std::string::npos);
}
