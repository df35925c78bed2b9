// The archive convention (coupling/hdf5_archive.h): a reader refuses a
// foreign kind, another format version, another fingerprint (naming the
// first differing entry), a damaged or truncated file and a file without
// the compax header, each with one Hdf5ArchiveError; a flipped byte
// anywhere in the file is caught before HDF5 reads it, and the same
// content gives the same bytes.

#include "coupling/hdf5_archive.h"

#include "tests/support/temporary_folder.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <thread>
#include <vector>

using compax::coupling::Hdf5ArchiveError;
using compax::coupling::Hdf5ArchiveReader;
using compax::coupling::Hdf5ArchiveWriter;
namespace fs = std::filesystem;

namespace
{
  class ArchiveIntegrity : public compax::testing::TemporaryFolderTest
  {
  protected:
    static std::string
    bytes(const std::string &path)
    {
      std::ifstream in(path, std::ios::binary);
      return {std::istreambuf_iterator<char>(in),
              std::istreambuf_iterator<char>()};
    }

    static void
    put(const std::string &path, const std::string &content)
    {
      std::ofstream(path, std::ios::binary | std::ios::trunc) << content;
    }

    /// The reason a reader gives for @p path (empty if it opens).
    static std::string
    refusal(const std::string                &path,
            const std::string                &kind,
            const std::optional<std::string> &parameters = std::nullopt)
    {
      try
        {
          Hdf5ArchiveReader reader(path, kind, parameters);
          return {};
        }
      catch (const Hdf5ArchiveError &e)
        {
          EXPECT_EQ(std::string(e.reason()).find('\n'), std::string::npos);
          return e.reason();
        }
    }
  };

  const std::string parameters = "Material/Radius = 0.0002\n"
                                 "Material/Young's modulus = 5000000000\n"
                                 "Packing/Seed = 1\n";

  /// A small archive of kind "die-compaction" with arrays, text and
  /// attributes.
  void
  write_sample(const std::string &path)
  {
    Hdf5ArchiveWriter w(path, {"die-compaction", parameters});
    w.write_array("bed/positions", {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}, {2, 3});
    w.write_array("rows", {0.5, 0.25, 1.0 / 3.0});
    w.write_text("notes", "fabric rows\n1,compaction,0.7\n");
    w.write_attribute("completed_targets", 7.0);
    w.write_attribute("label", std::string("attribute text to flip"));
    w.commit();
  }
} // namespace

TEST_F(ArchiveIntegrity, IntactArchiveOpensWithItsKindAndParameters)
{
  const std::string path = file("a.h5");
  write_sample(path);
  const Hdf5ArchiveReader r(path, "die-compaction", parameters);
  EXPECT_EQ(r.kind(), "die-compaction");
  EXPECT_EQ(r.parameters(), parameters);
  EXPECT_EQ(r.read_array("rows"), (std::vector<double>{0.5, 0.25, 1.0 / 3.0}));
  EXPECT_EQ(r.read_text("notes"), "fabric rows\n1,compaction,0.7\n");
  EXPECT_EQ(r.read_attribute("completed_targets"), 7.0);
  EXPECT_EQ(r.read_text_attribute("label"), "attribute text to flip");
  EXPECT_EQ(r.read_text_attribute("format"), "compax-archive");
  EXPECT_EQ(r.read_attribute("format_version"), 2.0);
}

TEST_F(ArchiveIntegrity, ForeignKindIsRefusedNamingBoth)
{
  const std::string path = file("a.h5");
  write_sample(path);
  const std::string why = refusal(path, "rve");
  EXPECT_NE(why.find("is of kind 'die-compaction' (die compaction "
                     "checkpoint), not 'rve' (RVE checkpoint)"),
            std::string::npos)
    << why;
}

TEST_F(ArchiveIntegrity, OtherParametersAreRefusedNamingTheFirstEntry)
{
  const std::string path = file("a.h5");
  write_sample(path);
  std::string other = parameters;
  other.replace(other.find("0.0002"), 6, "0.00022");
  const std::string why = refusal(path, "die-compaction", other);
  EXPECT_NE(why.find("Material/Radius = 0.0002 in the archive, 0.00022 here"),
            std::string::npos)
    << why;
  // Entries missing on either side are named too.
  const std::string fewer = refusal(path,
                                    "die-compaction",
                                    "Material/Radius = 0.0002\n"
                                    "Material/Young's modulus = 5000000000\n");
  EXPECT_NE(fewer.find("Packing/Seed = 1 in the archive is not among"),
            std::string::npos)
    << fewer;
}

TEST_F(ArchiveIntegrity, TruncatedFilesAreRefused)
{
  const std::string path = file("a.h5");
  write_sample(path);
  const std::string content = bytes(path);
  for (const std::size_t keep : {std::size_t(0),
                                 std::size_t(100),
                                 content.size() / 2,
                                 content.size() - 1})
    {
      put(path, content.substr(0, keep));
      const std::string why = refusal(path, "die-compaction");
      EXPECT_TRUE(why.find("truncated") != std::string::npos
                  || why.find("empty") != std::string::npos)
        << keep << ": " << why;
    }
  put(path, content + "x");
  EXPECT_NE(refusal(path, "die-compaction").find("bytes more"),
            std::string::npos);
}

TEST_F(ArchiveIntegrity, AFlippedByteAnywhereIsRefused)
{
  const std::string path = file("a.h5");
  write_sample(path);
  const std::string content = bytes(path);
  const std::string flipped = file("flipped.h5");
  // Bytes all over the file: header, HDF5 structure, data, attributes
  // (about 350 positions; every byte takes a minute).
  const std::size_t stride = std::max<std::size_t>(1, content.size() / 350);
  for (std::size_t k = 0; k < content.size(); k += stride)
    {
      std::string damaged = content;
      damaged[k] ^= 0x10;
      put(flipped, damaged);
      EXPECT_FALSE(refusal(flipped, "die-compaction").empty())
        << "byte " << k << " of " << content.size();
    }
  // The attribute's text in particular.
  const auto at = content.find("attribute text to flip");
  ASSERT_NE(at, std::string::npos);
  std::string damaged = content;
  damaged[at + 3] ^= 1;
  put(flipped, damaged);
  EXPECT_NE(refusal(flipped, "die-compaction").find("checksum"),
            std::string::npos);
}

TEST_F(ArchiveIntegrity, FilesWithoutTheHeaderAreRefused)
{
  // An HDF5 file of an older compax (or another program).
  const std::string old = file("old.h5");
  {
    const hid_t f
      = H5Fcreate(old.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    H5Fclose(f);
  }
  EXPECT_NE(refusal(old, "die-compaction")
              .find("without the compax archive "
                    "header"),
            std::string::npos);
  const std::string text = file("notes.h5");
  put(text, "not an archive at all\n");
  EXPECT_NE(refusal(text, "die-compaction").find("not a compax archive"),
            std::string::npos);
  EXPECT_NE(refusal(dir.string(), "die-compaction").find("is a folder"),
            std::string::npos);
  EXPECT_NE(refusal(file("missing.h5"), "die-compaction").find("no such file"),
            std::string::npos);
}

TEST_F(ArchiveIntegrity, AnotherFormatVersionIsRefused)
{
  const std::string path = file("a.h5");
  write_sample(path);
  std::string content = bytes(path);
  const auto  at      = content.find("version 2\n");
  ASSERT_NE(at, std::string::npos);
  content[at + 8] = '3';
  put(path, content);
  EXPECT_NE(refusal(path, "die-compaction").find("format version '3'"),
            std::string::npos);
}

TEST_F(ArchiveIntegrity, SameContentGivesTheSameBytes)
{
  write_sample(file("a.h5"));
  // HDF5 would store modification times: a second later, the same bytes.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write_sample(file("b.h5"));
  EXPECT_EQ(bytes(file("a.h5")), bytes(file("b.h5")));
}

TEST_F(ArchiveIntegrity, ReservedAttributesCannotBeWritten)
{
  Hdf5ArchiveWriter w(file("a.h5"), {"die-compaction", ""});
  EXPECT_THROW(w.write_attribute("kind", std::string("rve")), Hdf5ArchiveError);
  EXPECT_THROW(w.write_attribute("checksum", 1.0), Hdf5ArchiveError);
}
