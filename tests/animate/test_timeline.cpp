// The animation's clock (src/animate/timeline.cpp).
#include <gtest/gtest.h>

#include "animate/timeline.hpp"
#include "scene/scene.hpp"

namespace pita::animate {
namespace {

scene::Scene scene_with(const std::string& animation) {
  return scene::parse_scene(R"({"method": "P6", "keyframes": [{"t": 1, "p": [0, 0], "m": 1, "w": 0},
      {"t": 2, "p": [1, 1], "m": 1, "w": 0.5}, {"t": 4, "p": [2, 0], "m": 1, "w": 1}])" +
                                (animation.empty() ? std::string() : ", \"animation\": " + animation) + "}",
                            "anim.json");
}

TEST(Timeline, DefaultsAreFourSecondsAtThirtyFramesLooping) {
  const Timeline timeline = make_timeline(scene_with(""));
  EXPECT_EQ(timeline.frames, 120);
  EXPECT_EQ(timeline.fps, 30.0);
  EXPECT_TRUE(timeline.loop);
  EXPECT_EQ(timeline.what, scene::Animation::What::motion);
  EXPECT_EQ(timeline.first, 1.0);
  EXPECT_EQ(timeline.last, 4.0);
  EXPECT_EQ(timeline.seconds(), 4.0);
}

TEST(Timeline, NotLoopingShowsBothEnds) {
  const Timeline timeline = make_timeline(scene_with(R"({"loop": false, "frames": 7})"));
  ASSERT_EQ(timeline.frames, 7);
  for (int k = 0; k < 7; ++k) EXPECT_DOUBLE_EQ(timeline.time(k), 1.0 + 3.0 * k / 6.0) << k;
  EXPECT_EQ(timeline.time(0), 1.0);
  EXPECT_EQ(timeline.time(6), 4.0);
}

TEST(Timeline, LoopingStopsOneStepShortOfTheEnd) {
  const Timeline timeline = make_timeline(scene_with(R"({"loop": true, "frames": 6})"));
  for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(timeline.time(k), 1.0 + 3.0 * k / 6.0) << k;
  EXPECT_DOUBLE_EQ(timeline.step(), 0.5);
}

TEST(Timeline, FlagsOverrideTheScene) {
  const scene::Scene scene = scene_with(R"({"duration": 2, "fps": 10})");
  EXPECT_EQ(make_timeline(scene).frames, 20);
  EXPECT_EQ(make_timeline(scene, {24.0, std::nullopt, std::nullopt}).frames, 48);
  EXPECT_EQ(make_timeline(scene, {std::nullopt, 3.0, std::nullopt}).frames, 30);
  const Timeline given = make_timeline(scene, {std::nullopt, 2.0, 50});
  EXPECT_EQ(given.frames, 50);
  EXPECT_DOUBLE_EQ(given.fps, 25.0);  // frames / duration
  EXPECT_EQ(make_timeline(scene, {std::nullopt, std::nullopt, 9}).fps, 10.0);
}

TEST(Timeline, RefusesFlagsOutOfRangeNamingThem) {
  const scene::Scene scene = scene_with("");
  const auto message = [&](const Overrides& o) {
    try {
      make_timeline(scene, o);
    } catch (const AnimationError& error) {
      return std::string(error.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(message({0.0, std::nullopt, std::nullopt}).find("--fps"), std::string::npos);
  EXPECT_NE(message({241.0, std::nullopt, std::nullopt}).find("--fps"), std::string::npos);
  EXPECT_NE(message({std::nullopt, 0.0, std::nullopt}).find("--duration"), std::string::npos);
  EXPECT_NE(message({std::nullopt, -1.0, std::nullopt}).find("--duration"), std::string::npos);
  EXPECT_NE(message({std::nullopt, std::nullopt, 1}).find("--frames"), std::string::npos);
  EXPECT_NE(message({std::nullopt, std::nullopt, 100001}).find("--frames"), std::string::npos);
  // 0.01 s at 30 fps is no frame at all
  EXPECT_NE(message({std::nullopt, 0.01, std::nullopt}).find("--duration"), std::string::npos);
}

TEST(Timeline, TrailIsTheEarlierFramesWithinTheMotion) {
  const Timeline timeline = make_timeline(scene_with(R"({"loop": false, "frames": 7, "trail": 3})"));
  EXPECT_EQ(timeline.trail_times(4.0), (std::vector<double>{2.5, 3.0, 3.5}));
  EXPECT_EQ(timeline.trail_times(1.5), (std::vector<double>{1.0}));
  EXPECT_TRUE(timeline.trail_times(1.0).empty());
}

TEST(Timeline, PatternRunsOverTau) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", "keyframes": [{"t": 0, "from": {"p": [0, 0], "m": 1, "w": 0}, "to": {"p": [0, 1], "m": 1, "w": 0}},
          {"t": 5, "p": [1, 1], "m": 1, "w": 0.5}, {"t": 9, "p": [2, 0], "m": 1, "w": 1}], "animation": {"loop": false, "frames": 5}})",
      "pattern.json");
  const Timeline timeline = make_timeline(scene);
  EXPECT_EQ(timeline.what, scene::Animation::What::pattern);
  EXPECT_EQ(timeline.first, 0.0);
  EXPECT_EQ(timeline.last, 1.0);
  EXPECT_EQ(timeline.time(2), 0.5);
}

TEST(Timeline, PatternTauFollowsTheScenesEase) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", "keyframes": [{"t": 0, "from": {"p": [0, 0], "m": 1, "w": 0}, "to": {"p": [0, 1], "m": 1, "w": 0}},
          {"t": 5, "p": [1, 1], "m": 1, "w": 0.5}, {"t": 9, "p": [2, 0], "m": 1, "w": 1}], "timing": {"ease": "ease-in-out"}})",
      "pattern.json");
  const Timeline timeline = make_timeline(scene);
  EXPECT_EQ(timeline.tau(0.0), 0.0);
  EXPECT_NEAR(timeline.tau(1.0), 1.0, 1e-15);
  EXPECT_NEAR(timeline.tau(0.5), 0.5, 1e-12);  // CSS ease-in-out is symmetric
  EXPECT_LT(timeline.tau(0.2), 0.2);           // slow in
  EXPECT_GT(timeline.tau(0.8), 0.8);           // slow out
  // without timing, tau is the time itself
  const Timeline plain = make_timeline(scene::parse_scene(
      R"({"method": "P6", "keyframes": [{"t": 0, "from": {"p": [0, 0], "m": 1, "w": 0}, "to": {"p": [0, 1], "m": 1, "w": 0}},
          {"t": 5, "p": [1, 1], "m": 1, "w": 0.5}, {"t": 9, "p": [2, 0], "m": 1, "w": 1}]})",
      "plain.json"));
  EXPECT_EQ(plain.tau(0.3), 0.3);
}

TEST(Timeline, ASlowFpsCannotPlayForAges) {
  try {
    make_timeline(scene_with(""), {1e-300, std::nullopt, 2});
    ADD_FAILURE() << "accepted";
  } catch (const AnimationError& error) {
    EXPECT_NE(std::string(error.what()).find("--fps"), std::string::npos) << error.what();
  }
}

TEST(Timeline, PoseScenesRunOverTheirPoses) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "SAM", "poses": [{"t": 0.5, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1.5, "matrix": [[0, -1, 2], [1, 0, 0]]}]})",
      "poses.json");
  const Timeline timeline = make_timeline(scene);
  EXPECT_EQ(timeline.first, 0.5);
  EXPECT_EQ(timeline.last, 1.5);
}

// Keyframes in the order given ("knots": "as-given", docs/paper-notes.md N41)
// play from the least knot to the greatest, not from the first listed.
TEST(Timeline, KeyframesAsGivenRunFromTheLeastKnotToTheGreatest) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", "options": {"knots": "as-given"}, "keyframes": [{"t": 2, "p": [0, 0], "m": 1, "w": 0},
      {"t": 1, "p": [1, 1], "m": 1, "w": 0.5}, {"t": 4, "p": [2, 0], "m": 1, "w": 1}]})",
      "as-given.json");
  const Timeline timeline = make_timeline(scene);
  EXPECT_EQ(timeline.first, 1.0);
  EXPECT_EQ(timeline.last, 4.0);
}

}  // namespace
}  // namespace pita::animate
