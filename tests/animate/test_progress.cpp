// The progress of long work (src/animate/progress.cpp): off a terminal, plain
// lines when asked for (a sweep), nothing otherwise, nothing in CI or when
// silenced. stderr is redirected to a file for the test.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "animate/progress.hpp"

namespace pita::animate {
namespace {

// What `work` writes on stderr, with stderr a file and CI as given.
template <typename Work>
std::string stderr_of(Work work, const char* ci) {
  // A file of this process's own: ctest runs the tests of this file in
  // parallel processes, and a shared name let one truncate another's output.
  static int calls = 0;
  const std::string path =
      (std::filesystem::temp_directory_path() /
       ("pita-test-progress-" + std::to_string(::getpid()) + "-" + std::to_string(++calls) + ".txt"))
          .string();
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  const int file = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ::dup2(file, STDERR_FILENO);
  ::close(file);
  const std::string old_ci = std::getenv("CI") ? std::getenv("CI") : "";
  const bool had_ci = std::getenv("CI") != nullptr;
  if (ci != nullptr) {
    ::setenv("CI", ci, 1);
  } else {
    ::unsetenv("CI");
  }
  work();
  std::fflush(stderr);
  ::dup2(saved, STDERR_FILENO);
  ::close(saved);
  if (had_ci) {
    ::setenv("CI", old_ci.c_str(), 1);
  } else {
    ::unsetenv("CI");
  }
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(path);
  return text.str();
}

void count_to_three(bool enabled, bool plain) {
  Progress progress("pita sweep", 3, enabled, plain, std::chrono::milliseconds(1));
  for (int done = 1; done <= 3; ++done) {
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
    progress.update(done);
  }
}

TEST(Progress, PlainLinesOffATerminalWithRateAndEta) {
  const std::string text = stderr_of([] { count_to_three(true, true); }, nullptr);
  EXPECT_NE(text.find("pita sweep: 1/3 (33%), "), std::string::npos) << text;
  EXPECT_NE(text.find("/s, ETA "), std::string::npos) << text;
  EXPECT_NE(text.find("pita sweep: 3/3 (100%)"), std::string::npos) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos) << text;  // lines, not a redrawn bar
}

// Whether to show progress is the caller's: the CLI asks for none with
// --quiet or in CI (cli/environment.cpp; tests/cli/test_animate.cpp runs pita
// on a terminal with CI=true). Progress itself reads no environment.
TEST(Progress, NothingWhenNotAskedOrOffATerminal) {
  EXPECT_EQ(stderr_of([] { count_to_three(true, false); }, nullptr), "");  // the bar needs a terminal
  EXPECT_EQ(stderr_of([] { count_to_three(false, true); }, nullptr), "");  // not enabled (--quiet, CI)
  EXPECT_NE(stderr_of([] { count_to_three(true, true); }, "true"), "");    // CI is not read here
}

}  // namespace
}  // namespace pita::animate
