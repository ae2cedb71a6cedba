// What every scene ends with (src/scene/scene_tail_reader.cpp): "golden",
// "claims", "lint" and "animation", read once for arrow scenes and pose
// scenes of either dimension.
#include <string>

#include <gtest/gtest.h>

#include "scene/scene.hpp"

namespace pita::scene {
namespace {

const char* const kTail = R"(, "golden": {"number_tolerance": 0.5}, "lint": {"min_content_share": 0.1},
    "animation": {"duration": 2, "loop": false}})";

void expect_tail(const Scene& scene) {
  ASSERT_TRUE(scene.golden.numbers.has_value());
  EXPECT_EQ(*scene.golden.numbers, 0.5);
  EXPECT_TRUE(scene.has_animation);
  EXPECT_EQ(scene.animation.duration, 2.0);
  EXPECT_FALSE(scene.animation.loop);
  EXPECT_EQ(scene.animation.what, Animation::What::motion);
}

TEST(SceneTail, EveryKindReadsTheSameTail) {
  expect_tail(parse_scene(R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 1, "p": [1, 1], "m": 1, "w": 0}, {"t": 2, "p": [2, 0], "m": 1, "w": 0}])" +
                              std::string(kTail),
                          "s.json"));
  expect_tail(parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -1, 1], [1, 0, 0]]}])" +
                              std::string(kTail),
                          "s.json"));
  expect_tail(parse_scene(R"({"dimension": 3, "method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[0, -1, 0, 1], [1, 0, 0, 0], [0, 0, 1, 0]]}])" +
                              std::string(kTail),
                          "s.json"));
}

TEST(SceneTail, WithoutAnimationTheDefaultPlaysTheMotion) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -1, 1], [1, 0, 0]]}]})",
                                  "s.json");
  EXPECT_FALSE(scene.has_animation);
  EXPECT_EQ(scene.animation.what, Animation::What::motion);
  EXPECT_FALSE(scene.golden.numbers.has_value());
}

}  // namespace
}  // namespace pita::scene
