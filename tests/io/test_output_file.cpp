// Writing outputs atomically (src/io/output_file.cpp): the bytes arrive
// whole, replace what was there, leave no temporary file behind (nor one
// registered for the interrupt cleanup), get the ordinary permissions, a set
// of files is written all or none, and a failure names the path and the reason.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/interrupt.hpp"
#include "io/output_file.hpp"

namespace pita::io {
namespace {

namespace fs = std::filesystem;

class OutputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pita-test-output-file-" + std::to_string(::getpid()) + "-" +
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

// Nothing stays registered for the interrupt cleanup after a write, whether it
// succeeded or not: a later signal must not remove a finished output.
TEST_F(OutputFile, NothingStaysInFlight) {
  write_file_atomically(dir_ / "figure.svg", "<svg/>");
  EXPECT_EQ(remove_in_flight(), 0u);
  EXPECT_THROW(write_file_atomically(dir_ / "no" / "figure.svg", "<svg/>"), std::runtime_error);
  EXPECT_EQ(remove_in_flight(), 0u);
  fs::create_directory(dir_ / "busy.svg");
  EXPECT_THROW(write_file_atomically(dir_ / "busy.svg", "<svg/>"), std::runtime_error);
  EXPECT_EQ(remove_in_flight(), 0u);
  EXPECT_TRUE(fs::exists(dir_ / "figure.svg"));
}

using Files = std::vector<std::pair<fs::path, std::string>>;

TEST_F(OutputFile, WritesASetWhole) {
  const Files files = {
      {dir_ / "x.svg", "<svg/>"}, {dir_ / "x.png", std::string("\x89PNG\0", 5)}, {dir_ / "x.pdf", "%PDF-"}};
  write_files_atomically(files);
  for (const auto& [path, bytes] : files) EXPECT_EQ(read(path), bytes) << path;
  EXPECT_EQ(entries(), 3u);
  EXPECT_EQ(remove_in_flight(), 0u);
  write_files_atomically(Files{});  // an empty set writes nothing
  EXPECT_EQ(entries(), 3u);
}

// A directory in the way of the PNG: the SVG of the same set is not replaced
// either (the old one stays), and no temporary remains.
TEST_F(OutputFile, OneFailureLeavesTheWholeSetAsItWas) {
  write_file_atomically(dir_ / "x.svg", "old");
  fs::create_directory(dir_ / "x.png");
  const Files files = {{dir_ / "x.svg", "<svg/>"}, {dir_ / "x.png", "png"}};
  try {
    write_files_atomically(files);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()),
              (dir_ / "x.png").string() + ": cannot rename the finished file into place (Is a directory)");
  }
  EXPECT_EQ(read(dir_ / "x.svg"), "old");
  EXPECT_EQ(entries(), 2u);  // x.svg and the directory x.png
  EXPECT_EQ(remove_in_flight(), 0u);
}

// The second file's temporary cannot be created: the first one's is removed.
TEST_F(OutputFile, AFailedTemporaryRemovesTheOthers) {
  const Files files = {{dir_ / "x.svg", "<svg/>"}, {dir_ / "missing" / "x.png", "png"}};
  EXPECT_THROW(write_files_atomically(files), std::runtime_error);
  EXPECT_EQ(entries(), 0u);
  EXPECT_EQ(remove_in_flight(), 0u);
}

// More writers than slots for temporaries (a sweep's --jobs 256): each waits
// for a slot instead of failing, and every file arrives.
TEST_F(OutputFile, MoreWritersThanSlotsAllSucceed) {
  constexpr int kWriters = 4 * static_cast<int>(kInFlightSlots);
  std::vector<std::thread> writers;
  std::atomic<int> failed{0};
  for (int i = 0; i < kWriters; ++i) {
    writers.emplace_back([&, i] {
      try {
        const Files set = {{dir_ / (std::to_string(i) + ".svg"), "<svg/>"},
                           {dir_ / (std::to_string(i) + ".csv"), "index\n"}};
        write_files_atomically(set);
      } catch (const std::exception&) {
        ++failed;
      }
    });
  }
  for (std::thread& w : writers) w.join();
  EXPECT_EQ(failed.load(), 0);
  EXPECT_EQ(entries(), 2u * kWriters);
  EXPECT_EQ(remove_in_flight(), 0u);
}

// A reservation waits while the slots are reserved by others, and a set
// larger than every slot is refused rather than waited for forever.
TEST_F(OutputFile, ReservationsWaitForFreeSlots) {
  std::atomic<bool> second_done{false};
  std::thread second;
  {
    const InFlightReservation all(kInFlightSlots);
    second = std::thread([&] {
      const InFlightReservation one(1);
      second_done = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_FALSE(second_done.load());
  }
  second.join();
  EXPECT_TRUE(second_done.load());
  EXPECT_THROW(InFlightReservation(kInFlightSlots + 1), std::length_error);
}

// An edit's write (pita serve): the file is replaced only if it still holds
// what the edit read; a save made since (or a file gone) is left as it is,
// and no temporary remains either way.
TEST_F(OutputFile, ReplacesAFileOnlyIfItIsUnchanged) {
  const fs::path path = dir_ / "scene.json";
  write_file_atomically(path, "{\"m\": 1}");
  EXPECT_TRUE(replace_file_if_unchanged(path, "{\"m\": 1}", "{\"m\": 2}"));
  EXPECT_EQ(read(path), "{\"m\": 2}");
  // Saved by another program since the edit read {"m": 2}: kept.
  write_file_atomically(path, "{\"m\": 3}");
  EXPECT_FALSE(replace_file_if_unchanged(path, "{\"m\": 2}", "{\"m\": 4}"));
  EXPECT_EQ(read(path), "{\"m\": 3}");
  // Longer (the read stops one byte past what was expected) or gone: kept.
  write_file_atomically(path, "{\"m\": 3} ");
  EXPECT_FALSE(replace_file_if_unchanged(path, "{\"m\": 3}", "{\"m\": 4}"));
  EXPECT_EQ(read(path), "{\"m\": 3} ");
  fs::remove(path);
  EXPECT_FALSE(replace_file_if_unchanged(path, "{\"m\": 3}", "{\"m\": 4}"));
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(entries(), 0u);  // no temporary left
}

}  // namespace
}  // namespace pita::io
