// Which ffmpeg writes videos (src/animate/video.cpp): find_ffmpeg looks only at
// the files it is given; the front ends read PITA_FFMPEG and PATH. Videos end
// to end (ffmpeg, its errors, interrupts) are in tests/cli/test_animate.cpp.
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "animate/video.hpp"

namespace pita::animate {
namespace {

namespace fs = std::filesystem;

class FindFfmpeg : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pita-test-find-ffmpeg-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "bin");
    fs::create_directories(dir_ / "empty");
    std::ofstream(dir_ / "bin" / "ffmpeg") << "#!/bin/sh\n";
    fs::permissions(dir_ / "bin" / "ffmpeg", fs::perms::owner_all);
    std::ofstream(dir_ / "plain") << "not executable\n";
    fs::permissions(dir_ / "plain", fs::perms::owner_read | fs::perms::owner_write);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(FindFfmpeg, TheGivenOneWhenExecutable) {
  const std::string given = (dir_ / "bin" / "ffmpeg").string();
  EXPECT_EQ(find_ffmpeg(given, std::nullopt), given);
  // Given, it is the answer even when the search path has another.
  EXPECT_EQ(find_ffmpeg(given, (dir_ / "empty").string()), given);
}

TEST_F(FindFfmpeg, AGivenOneThatCannotRunIsNone) {
  // Not executable, or missing: none, not the one on the search path.
  EXPECT_EQ(find_ffmpeg((dir_ / "plain").string(), (dir_ / "bin").string()), "");
  EXPECT_EQ(find_ffmpeg((dir_ / "missing").string(), (dir_ / "bin").string()), "");
}

TEST_F(FindFfmpeg, TheFirstOnTheSearchPath) {
  const std::string search_path = (dir_ / "empty").string() + ":" + (dir_ / "bin").string();
  EXPECT_EQ(find_ffmpeg(std::nullopt, search_path), (dir_ / "bin" / "ffmpeg").string());
  EXPECT_EQ(find_ffmpeg(std::nullopt, (dir_ / "empty").string()), "");
}

}  // namespace
}  // namespace pita::animate
