// The registry of temporary files in flight (src/io/interrupt.cpp), without
// signals: what is registered is removed by remove_in_flight, what was
// released is not, and a full registry or an overlong path is refused rather
// than left unprotected. The handler itself is tested through the real binary
// (tests/cli/test_interrupt.cpp).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "io/interrupt.hpp"

namespace pita::io {
namespace {

namespace fs = std::filesystem;

class InFlight : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pita-test-interrupt-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path touch(const std::string& name) const {
    std::ofstream(dir_ / name) << "unfinished";
    return dir_ / name;
  }

  fs::path dir_;
};

TEST_F(InFlight, RemovesWhatIsRegisteredAndNotWhatWasReleased) {
  const fs::path a = touch("a"), b = touch("b"), c = touch("c");
  const int slot_a = register_in_flight(a.string());
  const int slot_b = register_in_flight(b.string());
  ASSERT_GE(slot_a, 0);
  ASSERT_GE(slot_b, 0);
  EXPECT_NE(slot_a, slot_b);
  release_in_flight(slot_b);  // b was renamed into place, say
  EXPECT_EQ(remove_in_flight(), 1u);
  EXPECT_FALSE(fs::exists(a));
  EXPECT_TRUE(fs::exists(b));
  EXPECT_TRUE(fs::exists(c));  // never registered
  // The slot stays taken until its owner releases it; its file is gone already.
  EXPECT_EQ(remove_in_flight(), 1u);
  release_in_flight(slot_a);
  EXPECT_EQ(remove_in_flight(), 0u);
  release_in_flight(-1);  // ignored
}

// mkstemp fills in the name in the slot itself: the file it creates is the one
// the handler removes.
TEST_F(InFlight, MkstempCreatesTheRegisteredName) {
  const int slot = register_in_flight((dir_ / ".figure.svg.XXXXXX").string());
  ASSERT_GE(slot, 0);
  const int fd = ::mkstemp(slot_path(slot));
  ASSERT_GE(fd, 0);
  ::close(fd);
  const fs::path created = slot_path(slot);
  EXPECT_EQ(created.parent_path(), dir_);
  EXPECT_NE(created.filename().string(), ".figure.svg.XXXXXX");
  EXPECT_TRUE(fs::exists(created));
  EXPECT_EQ(remove_in_flight(), 1u);
  EXPECT_FALSE(fs::exists(created));
  EXPECT_TRUE(fs::is_empty(dir_));
  release_in_flight(slot);
}

// Registering a file that does not exist yet, or any more, is harmless.
TEST_F(InFlight, MissingFilesAreNoError) {
  const int slot = register_in_flight((dir_ / "never-created").string());
  ASSERT_GE(slot, 0);
  EXPECT_EQ(remove_in_flight(), 1u);
  release_in_flight(slot);
}

TEST_F(InFlight, FullRegistryAndOverlongPathsAreRefused) {
  EXPECT_EQ(register_in_flight(std::string(kInFlightPathMax, 'x')), -1);
  const int fits = register_in_flight(std::string(kInFlightPathMax - 1, 'x'));
  EXPECT_GE(fits, 0);
  release_in_flight(fits);

  std::vector<int> taken;
  for (std::size_t i = 0; i < kInFlightSlots; ++i) {
    const int slot = register_in_flight((dir_ / std::to_string(i)).string());
    ASSERT_GE(slot, 0) << i;
    taken.push_back(slot);
  }
  EXPECT_EQ(register_in_flight((dir_ / "one-too-many").string()), -1);
  release_in_flight(taken.back());
  const int again = register_in_flight((dir_ / "one-more").string());
  EXPECT_EQ(again, taken.back());  // the released slot is reused
  taken.back() = again;
  for (const int slot : taken) release_in_flight(slot);
  EXPECT_EQ(remove_in_flight(), 0u);
}

}  // namespace
}  // namespace pita::io
