// pita watch (src/cli/watch.cpp): it renders the scene, renders again on each
// save of the scene (in place or by a rename over it) or of an image it uses,
// keeps the last good output when a save is bad and says why (a deleted
// scene, a folder in its place), watches a folder removed and made again,
// and leaves no temporary behind after a hundred saves or a signal.
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include "cli/run_pita.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const std::string kWatchScene = R"({"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0.3},
    {"t": 1, "p": [4, 1], "m": 0.6, "w": )";

std::string sma_scene(double w) { return kWatchScene + std::to_string(w) + "}]}"; }

// Waits (at most a minute: a sanitized pita is slow) until `done` holds.
template <class Condition>
bool eventually(Condition done) {
  const auto give_up = std::chrono::steady_clock::now() + 60s;
  while (!done()) {
    if (std::chrono::steady_clock::now() > give_up) return false;
    std::this_thread::sleep_for(20ms);
  }
  return true;
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A running `pita watch` and what it printed so far.
class Watching {
 public:
  Watching(const ScratchDir& dir, std::vector<std::string> args) : started_(start_pita(args, dir.path())) {}
  std::string out() const { return read_file(started_.capture->path() / "stdout"); }
  std::string err() const { return read_file(started_.capture->path() / "stderr"); }
  bool renders(std::size_t n) const {
    return eventually([&] { return count_of(out(), "wrote ") >= n; });
  }
  RunResult stop(int sig = SIGTERM) {
    ::kill(started_.pid, sig);
    return finish_pita(started_);
  }

 private:
  Started started_;
};

// Saves as an editor that writes a new file and renames it over the old one.
void save_by_rename(const ScratchDir& dir, const std::string& name, const std::string& text) {
  dir.write(".~" + name, text);
  fs::rename(dir.path() / (".~" + name), dir.path() / name);
}

TEST(Watch, RendersThenRendersAgainOnEverySave) {
  ScratchDir dir;
  dir.write("s.json", sma_scene(3.6));
  Watching watch(dir, {"watch", "s.json", "-o", "out.svg"});
  ASSERT_TRUE(watch.renders(1)) << watch.err();
  const std::string first = read_file(dir.path() / "out.svg");
  EXPECT_TRUE(eventually([&] { return watch.err().find("watching s.json") != std::string::npos; }));
  dir.write("s.json", sma_scene(2.0));  // in place
  ASSERT_TRUE(watch.renders(2)) << watch.err();
  const std::string second = read_file(dir.path() / "out.svg");
  EXPECT_NE(second, first);
  save_by_rename(dir, "s.json", sma_scene(3.6));
  ASSERT_TRUE(watch.renders(3)) << watch.err();
  EXPECT_EQ(read_file(dir.path() / "out.svg"), first);  // the same scene draws the same bytes
  const RunResult stopped = watch.stop();
  EXPECT_EQ(stopped.exit_code, 128 + SIGTERM);
  EXPECT_EQ(hidden_in(dir.path()), std::vector<std::string>{});
}

TEST(Watch, ABadSaveKeepsTheLastGoodOutputAndSaysWhereTheErrorIs) {
  ScratchDir dir;
  dir.write("s.json", sma_scene(3.6));
  Watching watch(dir, {"watch", "s.json", "-o", "out.svg"});
  ASSERT_TRUE(watch.renders(1)) << watch.err();
  const std::string good = read_file(dir.path() / "out.svg");
  dir.write("s.json", "{\"method\": \"SMA\",\n  \"keyframes\": [");
  ASSERT_TRUE(eventually([&] { return watch.err().find("s.json:2:") != std::string::npos; })) << watch.err();
  EXPECT_NE(watch.err().find("the last good output is kept"), std::string::npos);
  save_by_rename(dir, "s.json", kWatchScene + "3.6, \"m\": -1}]}");
  ASSERT_TRUE(eventually([&] { return watch.err().find("s.json: /keyframes/1") != std::string::npos; })) << watch.err();
  EXPECT_EQ(read_file(dir.path() / "out.svg"), good);
  dir.write("s.json", sma_scene(2.0));
  ASSERT_TRUE(watch.renders(2)) << watch.err();
  EXPECT_NE(read_file(dir.path() / "out.svg"), good);
  watch.stop();
}

TEST(Watch, SavingAnImageRendersAgainWithTheNewImage) {
  ScratchDir dir;
  fs::copy_file(fs::path(PITA_SOURCE_DIR) / "tests/data/bad/images/tiny.png", dir.path() / "picture.png");
  dir.write("s.json", kWatchScene + R"(3.6}], "shapes": [{"image": "picture.png", "box": [[0, 0], [1, 1]]}],
      "layers": [{"type": "shapes"}]})");
  Watching watch(dir, {"watch", "s.json", "-o", "out.png"});
  ASSERT_TRUE(watch.renders(1)) << watch.err();
  EXPECT_TRUE(eventually([&] { return watch.err().find("and 1 image") != std::string::npos; })) << watch.err();
  const std::string first = read_file(dir.path() / "out.png");
  // Another picture of the same size: a cache that kept the old one would draw the same bytes.
  fs::copy_file(fs::path(PITA_SOURCE_DIR) / "scenes/images/picture.png", dir.path() / ".new.png");
  fs::rename(dir.path() / ".new.png", dir.path() / "picture.png");
  ASSERT_TRUE(watch.renders(2)) << watch.err();
  EXPECT_NE(read_file(dir.path() / "out.png"), first);
  watch.stop();
}

TEST(Watch, AHundredSavesInARowLeaveTheLastFigureAndNoTemporary) {
  ScratchDir dir;
  dir.write("s.json", sma_scene(3.6));
  Watching watch(dir, {"watch", "s.json", "-o", "out", "--format", "svg,png"});
  ASSERT_TRUE(watch.renders(2)) << watch.err();  // two files per render
  for (int i = 0; i < 100; ++i) save_by_rename(dir, "s.json", sma_scene(1.0 + 0.01 * i));
  // The figure of the last save, as `pita render` draws it.
  ScratchDir reference;
  reference.write("s.json", sma_scene(1.0 + 0.01 * 99));
  ASSERT_EQ(run_pita({"render", "s.json", "-o", "ref.svg"}, reference.path()).exit_code, 0);
  const std::string expected = read_file(reference.path() / "ref.svg");
  EXPECT_TRUE(eventually([&] { return read_file(dir.path() / "out" / "s.svg") == expected; }));
  const RunResult stopped = watch.stop(SIGINT);
  EXPECT_EQ(stopped.exit_code, 128 + SIGINT);
  EXPECT_EQ(hidden_in(dir.path()), std::vector<std::string>{});
  EXPECT_EQ(hidden_in(dir.path() / "out"), std::vector<std::string>{});
}

// Issue 60: a scene deleted is "no such file" (not malformed JSON), one
// replaced by a folder "a directory"; the next good save renders again.
TEST(Watch, ADeletedSceneAndAFolderInItsPlaceSayWhatTheyAre) {
  ScratchDir dir;
  dir.write("s.json", sma_scene(3.6));
  Watching watch(dir, {"watch", "s.json", "-o", "out.svg"});
  ASSERT_TRUE(watch.renders(1)) << watch.err();
  const std::string good = read_file(dir.path() / "out.svg");
  fs::remove(dir.path() / "s.json");
  ASSERT_TRUE(eventually([&] {
    return watch.err().find("s.json: cannot open the scene file (No such file") != std::string::npos;
  })) << watch.err();
  fs::create_directory(dir.path() / "s.json");
  ASSERT_TRUE(eventually([&] {
    return watch.err().find("s.json: cannot read the scene file: it is a directory") != std::string::npos;
  })) << watch.err();
  EXPECT_EQ(watch.err().find("malformed"), std::string::npos) << watch.err();
  EXPECT_EQ(watch.err().find("basic_filebuf"), std::string::npos) << watch.err();
  EXPECT_EQ(read_file(dir.path() / "out.svg"), good);
  fs::remove(dir.path() / "s.json");
  dir.write("s.json", sma_scene(2.0));
  ASSERT_TRUE(watch.renders(2)) << watch.err();
  watch.stop();
}

// Issue 60: the scene's folder removed and made again (`rm -r d; mkdir d;
// cp s.json d/`) is watched again: the scene is rendered again, and so is
// its next save.
TEST(Watch, TheScenesFolderRemovedAndMadeAgainIsWatchedAgain) {
  ScratchDir dir;
  dir.write("d/s.json", sma_scene(3.6));
  Watching watch(dir, {"watch", "d/s.json", "-o", "out.svg"});
  ASSERT_TRUE(watch.renders(1)) << watch.err();
  ASSERT_TRUE(eventually([&] { return watch.err().find("watching d/s.json") != std::string::npos; }));
  const std::string first = read_file(dir.path() / "out.svg");
  fs::remove_all(dir.path() / "d");
  ASSERT_TRUE(eventually([&] { return watch.err().find("No such file") != std::string::npos; })) << watch.err();
  fs::create_directory(dir.path() / "d");
  dir.write("d/s.json", sma_scene(2.0));
  ASSERT_TRUE(watch.renders(2)) << watch.err();
  EXPECT_TRUE(eventually([&] { return read_file(dir.path() / "out.svg") != first; }));
  const std::string second = read_file(dir.path() / "out.svg");
  dir.write("d/s.json", sma_scene(3.6));
  ASSERT_TRUE(watch.renders(3)) << watch.err();
  EXPECT_TRUE(eventually([&] { return read_file(dir.path() / "out.svg") == first; }));
  EXPECT_NE(second, first);
  watch.stop();
}

TEST(Watch, MaxRendersEndsIt) {
  ScratchDir dir;
  dir.write("s.json", sma_scene(3.6));
  const RunResult result = run_pita({"watch", "s.json", "-o", "out.svg", "--max-renders", "1"}, dir.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out, "wrote out.svg\n");
}

TEST(Watch, BadOptionsAndMissingScenesAreBadInput) {
  ScratchDir dir;
  dir.write("s.json", sma_scene(3.6));
  RunResult result = run_pita({"watch", "s.json", "-o", "out.svg", "--scale", "100", "--max-renders", "1"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--scale"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out.svg"));
  result = run_pita({"watch", "s.json"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--output"), std::string::npos) << result.err;
  result = run_pita({"watch", "no-folder/s.json", "-o", "out.svg"}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("cannot watch"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace pita::test
