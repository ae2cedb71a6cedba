// "animation" (src/scene/animation_reader.cpp; docs/reference/animate.md "Animation"): the
// defaults, what each field sets, the frames that duration x fps gives, and
// "what" following whether a keyframe moves. Refusals through pita:
// tests/data/bad/animation-*.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/animation_reader.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using detail::Json;
using detail::JsonReader;
using test::p6_with;

using test::kReader;

using test::failure;

Animation read(const std::string& text, bool moving = false) {
  return detail::read_animation<Layer>(kReader, Json::parse(text), "/animation", moving);
}

std::string refusal(const std::string& text, bool moving = false) {
  return failure([&] { read(text, moving); });
}

// A P6 scene whose middle keyframe moves, with `extra` top-level members.
std::string moving_with(const std::string& extra) {
  return R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 0.5, "from": {"p": [1, 1], "m": 1, "w": 0}, "to": {"p": [1, -1], "m": 2, "w": 1}},
    {"t": 1, "p": [2, 0], "m": 1, "w": 0}])" +
         extra + "}";
}

TEST(AnimationReader, DefaultsFollowWhetherAKeyframeMoves) {
  const Animation still = detail::default_animation(false);
  EXPECT_EQ(still.what, Animation::What::motion);
  EXPECT_EQ(still.duration, 4.0);
  EXPECT_EQ(still.fps, 30.0);
  EXPECT_FALSE(still.frames.has_value());  // round(duration x fps) when played
  EXPECT_TRUE(still.loop);
  EXPECT_EQ(still.trail, 0);
  EXPECT_EQ(still.overlay, std::vector<double>{0.0});
  EXPECT_EQ(detail::default_animation(true).what, Animation::What::pattern);

  // An empty object is the default too.
  EXPECT_EQ(read("{}").what, Animation::What::motion);
  EXPECT_EQ(read("{}", true).what, Animation::What::pattern);
  EXPECT_EQ(read("{}", true).duration, 4.0);
}

TEST(AnimationReader, ReadsEveryField) {
  const Animation animation =
      read(R"({"duration": 2.5, "fps": 24, "frames": 61, "loop": false, "what": "motion", "trail": 7,
               "overlay": [0, 0.25, 1]})",
           true);
  EXPECT_EQ(animation.duration, 2.5);
  EXPECT_EQ(animation.fps, 24.0);
  ASSERT_TRUE(animation.frames.has_value());
  EXPECT_EQ(*animation.frames, 61);  // given: not round(2.5 x 24) = 60
  EXPECT_FALSE(animation.loop);
  EXPECT_EQ(animation.what, Animation::What::motion);  // given: not the moving default
  EXPECT_EQ(animation.trail, 7);
  EXPECT_EQ(animation.overlay, (std::vector<double>{0.0, 0.25, 1.0}));
  EXPECT_EQ(read(R"({"what": "pattern"})", true).what, Animation::What::pattern);
}

TEST(AnimationReader, BoundsAreInclusiveWhereTheSchemaSays) {
  EXPECT_EQ(read(R"({"fps": 240})").fps, kMaxFps);
  EXPECT_EQ(read(R"({"duration": 86400, "frames": 2})").duration, kMaxAnimationDuration);
  EXPECT_EQ(*read(R"({"frames": 2})").frames, kMinAnimationFrames);
  EXPECT_EQ(*read(R"({"frames": 100000})").frames, kMaxAnimationFrames);
  EXPECT_EQ(read(R"({"trail": 100})").trail, kMaxTrail);
  EXPECT_EQ(read(R"({"frames": 3.0})").frames, 3);  // 3.0 is an integer
  EXPECT_EQ(refusal(R"({"fps": 0})"), "/animation/fps: must be > 0 and <= 240 (got 0)");
  EXPECT_EQ(refusal(R"({"fps": 240.5})"), "/animation/fps: must be > 0 and <= 240 (got 240.5)");
  EXPECT_EQ(refusal(R"({"duration": 0})"), "/animation/duration: must be > 0 and <= 86400 (got 0)");
  EXPECT_EQ(refusal(R"({"duration": -1})"), "/animation/duration: must be > 0 and <= 86400 (got -1)");
  EXPECT_EQ(refusal(R"({"frames": 1})"), "/animation/frames: must be an integer between 2 and 100000 (got 1)");
  EXPECT_EQ(refusal(R"({"trail": -1})"), "/animation/trail: must be an integer between 0 and 100 (got -1)");
}

// Without "frames", round(duration x fps) must be a frame count pita can play.
TEST(AnimationReader, FramesFromDurationTimesFps) {
  EXPECT_EQ(refusal(R"({"duration": 0.05, "fps": 30})"), "(no error)");  // round(1.5) = 2
  EXPECT_EQ(refusal(R"({"duration": 0.04, "fps": 30})"),
            "/animation/duration: duration x fps = 0.04 x 30 gives 1 frames; an animation has 2 to 100000 frames");
  // The default duration (4 s) at 0.2 frames per second: named at "fps", the field given.
  EXPECT_EQ(refusal(R"({"fps": 0.2})"),
            "/animation/fps: duration x fps = 4 x 0.2 gives 1 frames; an animation has 2 to 100000 frames");
  EXPECT_EQ(refusal(R"({"duration": 1000, "fps": 100})"), "(no error)");  // 100000 frames
  EXPECT_EQ(refusal(R"({"duration": 1000, "fps": 100.01})"),
            "/animation/duration: duration x fps = 1000 x 100.01 gives 100010 frames; an animation has 2 to "
            "100000 frames");
  // "frames" given: duration x fps is not a frame count.
  EXPECT_EQ(refusal(R"({"duration": 0.01, "fps": 30, "frames": 10})"), "(no error)");
}

TEST(AnimationReader, PatternAndOverlayNeedAMovingKeyframe) {
  EXPECT_EQ(refusal(R"({"what": "pattern"})"),
            "/animation/what: \"pattern\" animates a pattern whose keyframes move, and no keyframe moves: give "
            "keyframes {\"t\": .., \"from\": ARROW, \"to\": ARROW}, or animate the \"motion\"");
  EXPECT_EQ(refusal(R"({"overlay": [0.5]})"),
            "/animation/overlay: \"overlay\" shows moving keyframes at several tau, and no keyframe moves");
  EXPECT_EQ(refusal(R"({"overlay": [0, 1.5]})", true), "/animation/overlay/1: must be between 0 and 1 (got 1.5)");
  EXPECT_EQ(refusal(R"({"overlay": []})", true),
            "/animation/overlay: must be an array of 1 to 64 values of tau in [0, 1] (got array [])");
  // A pose scene: nothing moves, and the messages say why.
  EXPECT_EQ(failure([] {
              detail::read_animation<PoseLayer>(kReader, Json::parse(R"({"what": "pattern"})"), "/animation", false);
            }),
            "/animation/what: \"pattern\" animates a pattern whose keyframes move, and a pose scene has no "
            "keyframes: animate the \"motion\"");
}

TEST(AnimationReader, UnknownFieldsAndWrongTypes) {
  EXPECT_EQ(refusal("[]"), "/animation: the animation must be an object (got array [])");
  EXPECT_EQ(refusal(R"({"fsp": 30})"), "/animation/fsp: unknown field \"fsp\"; did you mean \"fps\"?");
  EXPECT_EQ(refusal(R"({"loop": 1})"), "/animation/loop: must be true or false (got 1)");
  EXPECT_EQ(refusal(R"({"what": "Motion"})"),
            "/animation/what: must be \"motion\" or \"pattern\" (got string \"Motion\")");
}

// Through the scene readers: "what" defaults to "pattern" exactly when some
// keyframe of some panel moves; has_animation says whether the scene gave it.
TEST(AnimationReader, ScenesDefaultWhatByTheirKeyframes) {
  const Scene still = parse_scene(p6_with(""), "s.json");
  EXPECT_EQ(still.animation.what, Animation::What::motion);
  EXPECT_FALSE(still.has_animation);

  const Scene moving = parse_scene(moving_with(""), "s.json");
  EXPECT_EQ(moving.animation.what, Animation::What::pattern);
  EXPECT_FALSE(moving.has_animation);

  const Scene given = parse_scene(moving_with(R"(, "animation": {"duration": 2, "trail": 1})"), "s.json");
  EXPECT_TRUE(given.has_animation);
  EXPECT_EQ(given.animation.what, Animation::What::pattern);
  EXPECT_EQ(given.animation.duration, 2.0);
  EXPECT_EQ(given.animation.trail, 1);

  // Only a panel's keyframes move: the scene's animation is still a pattern's.
  const Scene panel = parse_scene(p6_with(R"(, "panels": ["P2", {"keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 1, "from": {"p": [1, 1], "m": 1, "w": 0}, "to": {"p": [1, 2], "m": 1, "w": 0}},
      {"t": 2, "p": [2, 0], "m": 1, "w": 0}]}], "animation": {"overlay": [0, 1]})"),
                                  "s.json");
  EXPECT_EQ(panel.animation.what, Animation::What::pattern);
  EXPECT_EQ(panel.animation.overlay, (std::vector<double>{0.0, 1.0}));

  // Pose scenes: "motion".
  const Scene poses = parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -2, 3], [2, 0, 1]]}], "animation": {"fps": 60, "trail": 4}})",
                                  "s.json");
  EXPECT_TRUE(poses.has_animation);
  EXPECT_EQ(poses.animation.what, Animation::What::motion);
  EXPECT_EQ(poses.animation.fps, 60.0);
  EXPECT_EQ(poses.animation.trail, 4);
}

}  // namespace
}  // namespace pita::scene
