// Saves of watched files (src/serve/file_watch.cpp): a write in place, a new
// file renamed over the old one and a deletion each count; a file that is not
// watched does not; a burst of saves is one answer; nothing is a timeout; a
// folder removed (or moved away) and made again is watched again.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "serve/file_watch.hpp"

namespace pita::serve {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

class FileWatcherTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pita-watch-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    write(scene(), "{}");
    write(other(), "x");
  }
  void TearDown() override { fs::remove_all(dir_); }
  static void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }
  fs::path scene() const { return fs::absolute(dir_ / "scene.json"); }
  // d/scene.json, made and watched: the scene of the tests whose folder goes and comes back.
  fs::path watched_in_folder(FileWatcher& watcher) const {
    fs::create_directories(dir_ / "d");
    write(dir_ / "d" / "scene.json", "{}");
    const fs::path scene = fs::absolute(dir_ / "d" / "scene.json");
    watcher.watch({scene});
    return scene;
  }
  fs::path other() const { return fs::absolute(dir_ / "other.txt"); }
  fs::path dir_;
};

TEST_F(FileWatcherTest, NothingSavedIsATimeout) {
  FileWatcher watcher;
  watcher.watch({scene()});
  EXPECT_TRUE(watcher.wait(milliseconds(50)).empty());
}

TEST_F(FileWatcherTest, AWriteInPlaceIsASave) {
  FileWatcher watcher;
  watcher.watch({scene()});
  write(scene(), R"({"a": 1})");
  const auto saved = watcher.wait(milliseconds(5000));
  ASSERT_EQ(saved.size(), 1u);
  EXPECT_EQ(*saved.begin(), scene());
}

TEST_F(FileWatcherTest, ARenameOverTheFileIsASave) {
  FileWatcher watcher;
  watcher.watch({scene()});
  write(dir_ / ".scene.json.swp", "{}");
  fs::rename(dir_ / ".scene.json.swp", scene());
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene()), 1u);
}

TEST_F(FileWatcherTest, ADeletionCounts) {
  FileWatcher watcher;
  watcher.watch({scene()});
  fs::remove(scene());
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene()), 1u);
}

TEST_F(FileWatcherTest, AFileNotWatchedDoesNotCount) {
  FileWatcher watcher;
  watcher.watch({scene()});
  write(other(), "y");
  EXPECT_TRUE(watcher.wait(milliseconds(200)).empty());
}

TEST_F(FileWatcherTest, ABurstIsOneAnswerAndNamesEveryFile) {
  FileWatcher watcher;
  watcher.watch({scene(), other()});
  for (int i = 0; i < 20; ++i) write(scene(), std::to_string(i));
  write(other(), "z");
  const auto saved = watcher.wait(milliseconds(5000));
  EXPECT_EQ(saved.size(), 2u);
  EXPECT_TRUE(watcher.wait(milliseconds(100)).empty());
}

TEST_F(FileWatcherTest, WatchingAnotherSetForgetsTheFirst) {
  FileWatcher watcher;
  watcher.watch({scene()});
  watcher.watch({other()});
  write(scene(), "{}");
  EXPECT_TRUE(watcher.wait(milliseconds(200)).empty());
  write(other(), "w");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(other()), 1u);
}

TEST_F(FileWatcherTest, AWriteThroughASymbolicLinkIsASaveOfTheLink) {
  fs::create_directories(dir_ / "elsewhere");
  write(dir_ / "elsewhere" / "target.json", "{}");
  fs::create_symlink(dir_ / "elsewhere" / "target.json", dir_ / "link.json");
  FileWatcher watcher;
  watcher.watch({dir_ / "link.json"});
  write(dir_ / "elsewhere" / "target.json", R"({"b": 2})");  // the editor writes the target
  const auto saved = watcher.wait(milliseconds(5000));
  ASSERT_EQ(saved.size(), 1u);
  EXPECT_EQ(*saved.begin(), fs::absolute(dir_ / "link.json"));
}

TEST_F(FileWatcherTest, AFolderThatDoesNotExistIsRefused) {
  FileWatcher watcher;
  EXPECT_THROW(watcher.watch({dir_ / "no-such-folder" / "scene.json"}), std::system_error);
}

// `rm -r d; mkdir d; cp scene.json d/`: the deletion counts, then the file
// made again in the folder made again, and later saves in it too.
TEST_F(FileWatcherTest, AFolderRemovedAndMadeAgainIsWatchedAgain) {
  FileWatcher watcher;
  const fs::path scene = watched_in_folder(watcher);
  fs::remove_all(dir_ / "d");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
  fs::create_directories(dir_ / "d");
  write(dir_ / "d" / "scene.json", R"({"c": 3})");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
  write(dir_ / "d" / "scene.json", R"({"c": 4})");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
}

// The folder made again between two waits, its file already in it: the file
// counts as saved when the folder is found again.
TEST_F(FileWatcherTest, AFolderMadeAgainWithItsFileCountsAsASave) {
  FileWatcher watcher;
  const fs::path scene = watched_in_folder(watcher);
  fs::remove_all(dir_ / "d");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
  fs::create_directories(dir_ / "d.new");
  write(dir_ / "d.new" / "scene.json", R"({"c": 5})");
  fs::rename(dir_ / "d.new", dir_ / "d");  // the whole folder moved into place
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
}

// Several levels gone: a/b/c removed from a, then made again in one go.
TEST_F(FileWatcherTest, NestedFoldersMadeAgainAreWatchedAgain) {
  fs::create_directories(dir_ / "a" / "b" / "c");
  write(dir_ / "a" / "b" / "c" / "scene.json", "{}");
  const fs::path scene = fs::absolute(dir_ / "a" / "b" / "c" / "scene.json");
  FileWatcher watcher;
  watcher.watch({scene});
  fs::remove_all(dir_ / "a");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
  fs::create_directories(dir_ / "a" / "b" / "c");
  write(dir_ / "a" / "b" / "c" / "scene.json", R"({"d": 1})");
  bool seen = false;
  for (int i = 0; i < 5 && !seen; ++i) seen = watcher.wait(milliseconds(2000)).count(scene) == 1;
  EXPECT_TRUE(seen);
  write(dir_ / "a" / "b" / "c" / "scene.json", R"({"d": 2})");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
}

// A folder moved away is no longer the scene's: saves in it do not count,
// and one moved back is watched again.
TEST_F(FileWatcherTest, AFolderMovedAwayAndBackIsWatchedAgain) {
  FileWatcher watcher;
  const fs::path scene = watched_in_folder(watcher);
  fs::rename(dir_ / "d", dir_ / "elsewhere");
  watcher.wait(milliseconds(300));
  write(dir_ / "elsewhere" / "scene.json", R"({"e": 1})");
  EXPECT_TRUE(watcher.wait(milliseconds(300)).empty());
  fs::rename(dir_ / "elsewhere", dir_ / "d");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
  write(dir_ / "d" / "scene.json", R"({"e": 2})");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
}

// Watching the same set again while its folder is gone keeps waiting for it
// (pita watch re-watches after each render).
TEST_F(FileWatcherTest, WatchingAgainWhileTheFolderIsGoneKeepsWaiting) {
  FileWatcher watcher;
  const fs::path scene = watched_in_folder(watcher);
  fs::remove_all(dir_ / "d");
  watcher.wait(milliseconds(300));
  EXPECT_NO_THROW(watcher.watch({scene}));
  fs::create_directories(dir_ / "d");
  write(dir_ / "d" / "scene.json", "{}");
  EXPECT_EQ(watcher.wait(milliseconds(5000)).count(scene), 1u);
}

}  // namespace
}  // namespace pita::serve
