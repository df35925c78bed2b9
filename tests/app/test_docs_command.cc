// `compax docs`: the parameter reference is generated from the same
// declarations --print-parameters prints, so every entry of every command
// is in it, and doc/parameters.md in the source tree is that file.

#include "app_test_support.h"

#include <sstream>

using namespace compax::testing;

class DocsCommand : public AppTest
{
};


TEST_F(DocsCommand, EveryPrintedEntryOfEveryCommandIsDocumented)
{
  const auto r = compax("docs -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string md = read(folder / "out" / "parameters.md");
  for (const std::string &command : parameter_commands)
    {
      EXPECT_NE(md.find("## compax " + command + "\n"), std::string::npos)
        << command;
      // Every "set <entry> = <default>" line of --print-parameters is a
      // table row "| `<entry>` | `<default>` |".
      const auto printed = compax(command + " --print-parameters");
      ASSERT_EQ(printed.exit_code, 0) << printed.err;
      std::istringstream lines(printed.out);
      std::size_t        entries = 0;
      for (std::string line; std::getline(lines, line);)
        {
          const auto set = line.find("set ");
          if (set == std::string::npos || line.find_first_not_of(' ') != set)
            continue;
          const auto  eq    = line.find(" = ", set);
          std::string entry = line.substr(set + 4, eq - set - 4);
          entry.erase(entry.find_last_not_of(' ') + 1);
          EXPECT_NE(md.find("| `" + entry + "` |"), std::string::npos)
            << command << ": " << entry;
          ++entries;
        }
      EXPECT_GT(entries, 0u) << command;
    }
}

TEST_F(DocsCommand, SourceTreeReferenceIsUpToDate)
{
  const auto r = compax("docs -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read(folder / "out" / "parameters.md"),
            read(std::filesystem::path(COMPAX_SOURCE_DIR) / "doc"
                 / "parameters.md"))
    << "regenerate it: compax docs -o <dir> and copy <dir>/parameters.md "
       "to doc/";
}
