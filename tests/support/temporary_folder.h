#pragma once

// A fresh folder per test for the unit tests that write files.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

namespace compax::testing
{
  /// Creates `dir`, named after the test and the process, before each test
  /// and removes it afterwards.
  class TemporaryFolderTest : public ::testing::Test
  {
  protected:
    void
    SetUp() override
    {
      const auto *info
        = ::testing::UnitTest::GetInstance()->current_test_info();
      dir = std::filesystem::temp_directory_path()
            / ("compax_" + std::string(info->test_suite_name()) + "_"
               + std::to_string(::getpid()) + "_" + info->name());
      std::filesystem::remove_all(dir);
      std::filesystem::create_directories(dir);
    }

    void
    TearDown() override
    {
      std::filesystem::remove_all(dir);
    }

    /// A path in the folder.
    std::string
    file(const std::string &name) const
    {
      return (dir / name).string();
    }

    std::filesystem::path dir;
  };
} // namespace compax::testing
