// Every bad scene of tests/data/bad/ (README.md there) through the real
// binary: `pita eval` and `pita render` exit 2, print nothing on stdout, name
// the file, the pointer (or line and column) and the reason on stderr, and
// render writes no file. The parser's side: tests/scene/test_bad_scenes.cpp.
//
// Each case is copied into a scratch directory, with the fixture folders it
// may name (images/), and given by its file name alone, as
// tests/cli/test_eval.cpp gives its scenes.
#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../bad_scene_cases.hpp"
#include "run_pita.hpp"

namespace pita::test {
namespace {

namespace fs = std::filesystem;

TEST(BadScenesCliFolder, EveryCaseHasItsExpectationAndThereAreEnough) {
  for (const std::string& problem : bad_scene_folder_problems()) ADD_FAILURE() << problem;
  EXPECT_GE(bad_scene_cases().size(), kMinBadScenes);
}

class BadSceneCli : public ::testing::TestWithParam<BadSceneCase> {
 protected:
  void SetUp() override {
    const BadSceneCase& bad = GetParam();
    std::string problem;
    expected = read_bad_scene_expectation(bad.expect(), problem);
    ASSERT_TRUE(expected.has_value()) << problem;
    file = bad.name + ".json";
    fs::copy_file(bad.scene(), dir.path() / file);
    for (const std::string& folder : kBadSceneFixtureFolders) {
      if (fs::is_directory(kBadScenesDir / folder)) {
        fs::copy(kBadScenesDir / folder, dir.path() / folder, fs::copy_options::recursive);
      }
    }
  }

  // The whole of stderr for one bad scene.
  std::string error_line() const { return "pita: " + file + expected->after_file() + "\n"; }

  const ScratchDir dir;
  std::string file;  // "<name>.json", in dir
  std::optional<BadSceneExpectation> expected;
};

TEST_P(BadSceneCli, EvalExitsTwoWithFilePointerAndReason) {
  const RunResult result = run_pita({"eval", file}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err, error_line());
}

TEST_P(BadSceneCli, RenderExitsTwoAndWritesNothing) {
  const ScratchDir out;
  const RunResult result = run_pita({"render", file, "-o", out.path().string()}, dir.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err, error_line());
  for (const auto& entry : fs::directory_iterator(out.path())) ADD_FAILURE() << "wrote " << entry.path();
  // Nothing beside the scene (and its fixtures) either.
  std::size_t fixtures = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir.path())) {
    const fs::path relative = fs::relative(entry.path(), dir.path());
    const std::string top = relative.begin()->string();
    if (std::find(kBadSceneFixtureFolders.begin(), kBadSceneFixtureFolders.end(), top) !=
        kBadSceneFixtureFolders.end()) {
      ++fixtures;
      continue;
    }
    EXPECT_EQ(relative.string(), file) << "wrote " << entry.path();
  }
  std::size_t copied = 0;
  for (const std::string& folder : kBadSceneFixtureFolders) {
    if (!fs::is_directory(kBadScenesDir / folder)) continue;
    ++copied;
    for ([[maybe_unused]] const auto& entry : fs::recursive_directory_iterator(kBadScenesDir / folder)) ++copied;
  }
  EXPECT_EQ(fixtures, copied) << "wrote into a fixture folder";
}

INSTANTIATE_TEST_SUITE_P(Files, BadSceneCli, ::testing::ValuesIn(bad_scene_cases()), bad_scene_test_name);

}  // namespace
}  // namespace pita::test
