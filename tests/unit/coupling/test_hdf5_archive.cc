#include "coupling/hdf5_archive.h"

#include "tests/support/temporary_folder.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using compax::coupling::Hdf5ArchiveError;
using compax::coupling::Hdf5ArchiveReader;
using compax::coupling::Hdf5ArchiveWriter;
namespace fs = std::filesystem;

namespace
{
  /// A fresh directory per test, removed afterwards.
  class Hdf5Archive : public compax::testing::TemporaryFolderTest
  {
  };

  const std::vector<double> positions
    = {0.0,
       -0.0,
       1.0 / 3.0,
       -2.5e-300,
       std::numeric_limits<double>::denorm_min(),
       std::numeric_limits<double>::max(),
       6.02214076e23};
} // namespace

TEST_F(Hdf5Archive, RoundTripIsExact)
{
  const std::string   path = file("state.h5");
  std::vector<double> matrix(12);
  for (std::size_t i = 0; i < matrix.size(); ++i)
    matrix[i] = 0.1 * double(i) - 1.0 / 7.0;

  {
    Hdf5ArchiveWriter writer(path, {"test", ""});
    writer.write_array("positions", positions);
    writer.write_array("rve/stress", matrix, {3, 4});
    writer.write_array("rve/empty", {});
    writer.write_attribute("time", 1.0 / 3.0);
    writer.write_attribute("tiny", 4.9e-324);
    writer.write_attribute("label", std::string("compax-checkpoint-1"));
    EXPECT_TRUE(fs::exists(path + ".tmp"));
    EXPECT_FALSE(fs::exists(path));
    writer.commit();
  }
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".tmp"));

  const Hdf5ArchiveReader reader(path);
  const auto              p = reader.read_array("positions");
  ASSERT_EQ(p.size(), positions.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      EXPECT_EQ(p[i], positions[i]) << i;
      EXPECT_EQ(std::signbit(p[i]), std::signbit(positions[i])) << i;
    }
  EXPECT_EQ(reader.read_array("rve/stress"), matrix);
  EXPECT_EQ(reader.array_shape("rve/stress"), (std::vector<hsize_t>{3, 4}));
  EXPECT_EQ(reader.array_shape("positions"),
            (std::vector<hsize_t>{positions.size()}));
  EXPECT_TRUE(reader.read_array("rve/empty").empty());
  EXPECT_EQ(reader.read_attribute("time"), 1.0 / 3.0);
  EXPECT_EQ(reader.read_attribute("tiny"), 4.9e-324);
  EXPECT_EQ(reader.read_text_attribute("label"), "compax-checkpoint-1");
  EXPECT_TRUE(reader.has_array("rve/stress"));
  EXPECT_FALSE(reader.has_array("rve")); // a group, not an array
  EXPECT_FALSE(reader.has_array("rve/strain"));
  EXPECT_TRUE(reader.has_attribute("time"));
  EXPECT_FALSE(reader.has_attribute("positions"));
}

TEST_F(Hdf5Archive, MissingFileGivesClearError)
{
  const std::string path = file("no_such_checkpoint.h5");
  try
    {
      Hdf5ArchiveReader reader(path);
      FAIL() << "opened a missing file";
    }
  catch (const Hdf5ArchiveError &e)
    {
      const std::string what = e.what();
      EXPECT_NE(what.find(path), std::string::npos) << what;
      EXPECT_NE(what.find("no such file"), std::string::npos) << what;
    }

  const std::string text = file("notes.h5");
  std::ofstream(text) << "not an HDF5 file\n";
  EXPECT_THROW(Hdf5ArchiveReader{text}, Hdf5ArchiveError);

  EXPECT_THROW(Hdf5ArchiveWriter(file("missing_dir/state.h5"), {"test", ""}),
               Hdf5ArchiveError);
}

TEST_F(Hdf5Archive, MissingOrMistypedEntriesThrow)
{
  const std::string path = file("state.h5");
  {
    Hdf5ArchiveWriter writer(path, {"test", ""});
    writer.write_array("x", {1.0, 2.0});
    writer.write_attribute("E", 1.0e9);
    writer.write_attribute("unit", std::string("Pa"));
    EXPECT_THROW(writer.write_array("x", {3.0}), Hdf5ArchiveError);
    EXPECT_THROW(writer.write_attribute("E", 2.0), Hdf5ArchiveError);
    EXPECT_THROW(writer.write_array("bad", {1.0, 2.0, 3.0}, {2, 2}),
                 Hdf5ArchiveError);
    EXPECT_THROW(writer.write_array("x/y", {1.0}), Hdf5ArchiveError);
    writer.commit();
    EXPECT_THROW(writer.write_attribute("late", 1.0), Hdf5ArchiveError);
    EXPECT_THROW(writer.commit(), Hdf5ArchiveError);
  }
  const Hdf5ArchiveReader reader(path);
  EXPECT_THROW(reader.read_array("y"), Hdf5ArchiveError);
  EXPECT_THROW(reader.read_array("x/y"), Hdf5ArchiveError);
  EXPECT_THROW(reader.read_attribute("nu"), Hdf5ArchiveError);
  EXPECT_THROW(reader.read_attribute("unit"), Hdf5ArchiveError);
  EXPECT_THROW(reader.read_text_attribute("E"), Hdf5ArchiveError);
  EXPECT_EQ(reader.read_attribute("E"), 1.0e9);
}

TEST_F(Hdf5Archive, UncommittedWriteKeepsPreviousArchive)
{
  const std::string path = file("checkpoint.h5");
  {
    Hdf5ArchiveWriter first(path, {"test", ""});
    first.write_attribute("step", 1.0);
    first.commit();
  }
  {
    Hdf5ArchiveWriter second(path, {"test", ""});
    second.write_attribute("step", 2.0);
    second.write_array("x", positions);
    // While the new checkpoint is written, the old one stays readable.
    EXPECT_EQ(Hdf5ArchiveReader(path).read_attribute("step"), 1.0);
    // ... and the writer is abandoned (as by an exception) before commit().
  }
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  const Hdf5ArchiveReader reader(path);
  EXPECT_EQ(reader.read_attribute("step"), 1.0);
  EXPECT_FALSE(reader.has_array("x"));

  {
    Hdf5ArchiveWriter third(path, {"test", ""});
    third.write_attribute("step", 3.0);
    third.commit();
  }
  EXPECT_EQ(Hdf5ArchiveReader(path).read_attribute("step"), 3.0);
}
