// Every bad scene of tests/data/bad/ (README.md there) through load_scene and
// the motion stage (a motion for every panel that draws one): it must be
// refused, by a SceneError or a motion::NoMotion, with exactly the pointer (or
// line and column) and the reason of its .expect file. The same cases through the pita binary:
// tests/cli/test_bad_scenes_cli.cpp.
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../bad_scene_cases.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "scene/scene.hpp"

namespace pita::scene {

// What `pita eval` and `pita render` do before drawing: read the scene, then
// build the motion of each panel that has one.
void load_and_build(const std::filesystem::path& path) {
  const Scene scene = load_scene(path);
  motion::Stage(scene).check();
  (void)motion::build_motion(scene);
}

namespace {

using test::BadSceneCase;
using test::BadSceneExpectation;

TEST(BadScenesFolder, EveryCaseHasItsExpectationAndThereAreEnough) {
  for (const std::string& problem : test::bad_scene_folder_problems()) ADD_FAILURE() << problem;
  EXPECT_GE(test::bad_scene_cases().size(), test::kMinBadScenes);
}

class BadScene : public ::testing::TestWithParam<BadSceneCase> {};

TEST_P(BadScene, IsRefusedWithItsPointerAndReason) {
  const BadSceneCase& bad = GetParam();
  std::string problem;
  const std::optional<BadSceneExpectation> expected = test::read_bad_scene_expectation(bad.expect(), problem);
  ASSERT_TRUE(expected.has_value()) << problem;
  try {
    load_and_build(bad.scene());
    FAIL() << bad.scene().string() << ": no error (expected" << expected->after_file() << ")";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.file(), bad.scene().string());
    if (expected->at_position) {
      EXPECT_EQ(std::to_string(error.line()) + ":" + std::to_string(error.column()),
                std::to_string(expected->line) + ":" + std::to_string(expected->column))
          << error.what();
      EXPECT_EQ(error.pointer(), "") << error.what();
    } else {
      EXPECT_EQ(error.pointer(), expected->pointer) << error.what();
      EXPECT_EQ(error.line(), 0) << error.what();
    }
    EXPECT_EQ(error.reason(), expected->reason) << error.what();
    EXPECT_EQ(std::string(error.what()), bad.scene().string() + expected->after_file());
  } catch (const motion::NoMotion& error) {
    EXPECT_FALSE(expected->at_position) << error.what();
    EXPECT_EQ(error.file(), bad.scene().string());
    EXPECT_EQ(error.pointer(), expected->pointer) << error.what();
    EXPECT_EQ(error.reason(), expected->reason) << error.what();
    EXPECT_EQ(std::string(error.what()), bad.scene().string() + expected->after_file());
  } catch (const std::exception& error) {
    FAIL() << bad.scene().string() << ": threw something other than SceneError or NoMotion: " << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Files, BadScene, ::testing::ValuesIn(test::bad_scene_cases()), test::bad_scene_test_name);

}  // namespace
}  // namespace pita::scene
