// Writing outputs atomically (src/render/output_file.cpp): the bytes arrive
// whole, replace what was there, leave no temporary file behind, get the
// ordinary permissions, and a failure names the path and the reason.
#include "render/output_file.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace pita::render {
namespace {

namespace fs = std::filesystem;

class OutputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pita-test-output-file-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }

  fs::path dir_;
};

TEST_F(OutputFile, WritesEveryByteAndNoTemporaryRemains) {
  const std::string bytes("\x89PNG\0\r\n\x1a\n tail", 14);
  write_file_atomically(dir_ / "figure.png", bytes);
  EXPECT_EQ(read(dir_ / "figure.png"), bytes);
  EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFile, ReplacesAnExistingFileWhole) {
  write_file_atomically(dir_ / "figure.svg", std::string(10000, 'a'));
  write_file_atomically(dir_ / "figure.svg", "<svg/>");
  EXPECT_EQ(read(dir_ / "figure.svg"), "<svg/>");
  write_file_atomically(dir_ / "figure.svg", "");
  EXPECT_EQ(fs::file_size(dir_ / "figure.svg"), 0u);
  EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFile, PermissionsAreThoseOfAnOrdinaryFile) {
  const mode_t saved = ::umask(022);
  write_file_atomically(dir_ / "figure.pdf", "%PDF-");
  ::umask(saved);
  EXPECT_EQ(fs::status(dir_ / "figure.pdf").permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read);
}

TEST_F(OutputFile, MissingDirectoryIsNamedWithTheReason) {
  const fs::path path = dir_ / "no" / "such" / "figure.png";
  try {
    write_file_atomically(path, "x");
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), path.string() + ": cannot create a temporary file in " +
                                             (dir_ / "no" / "such").string() + " (No such file or directory)");
  }
  EXPECT_EQ(entries(), 0u);
}

// A directory in the way: the rename fails and the temporary file is removed.
TEST_F(OutputFile, DirectoryInTheWayIsRefusedAndCleanedUp) {
  fs::create_directory(dir_ / "figure.svg");
  fs::create_directory(dir_ / "figure.svg" / "inside");
  try {
    write_file_atomically(dir_ / "figure.svg", "<svg/>");
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.rfind((dir_ / "figure.svg").string() + ": cannot rename the finished file into place (", 0), 0u)
        << what;
  }
  EXPECT_EQ(entries(), 1u);  // only the directory
}

}  // namespace
}  // namespace pita::render
