// The motion stage of a scene (src/motion/stage.cpp): each panel's motion
// built once and kept, a panel whose motion does not exist keeping its
// NoMotion until asked, a pose panel without poses having none, and the
// derived motions (another method, a layer's options, other keyframes)
// equal to the motions of the panels they describe.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/pitas/registry.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "scene/scene.hpp"
#include "support/keys.hpp"

namespace pita::motion {
namespace {

const std::string kStageKeyframes = R"("keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.25, "p": [3, 1.5], "m": 0.6, "w": 2},
    {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])";

// Two panels of arrows: P6, and P8 (with a timing of its own).
scene::Scene two_panels() {
  return scene::parse_scene(R"({"method": "P6", )" + kStageKeyframes + R"(, "panels": [{"title": "own"},
      {"method": "P8", "timing": {"ease": "ease-in-out"}}]})",
                            "s.json");
}

// Poses of the plane: the second panel's end pose is a half turn with
// unequal scales, which has no real logarithm (no SAM).
scene::Scene pose_panels() {
  return scene::parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -1, 2], [1, 0, 1]]}], "panels": [{"title": "turn"},
      {"poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[-1.5, 0, 0], [0, -0.6666, 0]]}]}]})",
                            "p.json");
}

void expect_same_frames(const SceneMotion& a, const SceneMotion& b) {
  for (const double t : {-0.5, 0.0, 0.1, 0.25, 0.6, 1.0, 1.5}) {
    const Arrow x = a.arrow_at(t), y = b.arrow_at(t);
    EXPECT_EQ(x.p, y.p) << t;
    EXPECT_EQ(x.m, y.m) << t;
    EXPECT_EQ(x.w, y.w) << t;
  }
}

TEST(Stage, HoldsEachPanelsMotionAsBuiltAlone) {
  const scene::Scene scene = two_panels();
  const Stage stage(scene);
  ASSERT_EQ(stage.size(), 2u);
  EXPECT_NO_THROW(stage.check());
  for (std::size_t i = 0; i < stage.size(); ++i) {
    EXPECT_EQ(&stage.panel(i), &scene.panels[i]);
    EXPECT_TRUE(stage.has_motion(i));
    EXPECT_EQ(stage.motion(i).method_id(), build_motion(scene, scene.panels[i]).method_id());
    expect_same_frames(stage.motion(i), build_motion(scene, scene.panels[i]));
  }
  // Kept, not rebuilt: the same object each time.
  EXPECT_EQ(&stage.motion(1), &stage.motion(1));
  EXPECT_EQ(stage.motion(1).method_id(), "P8");

  // With "panels", the scene's own motion is not one of them.
  EXPECT_FALSE(own_is_first_panel(scene));
  const scene::Scene plain = scene::parse_scene(R"({"method": "P6", )" + kStageKeyframes + "}", "s.json");
  EXPECT_TRUE(own_is_first_panel(plain));
  expect_same_frames(Stage(plain).motion(0), build_motion(plain));

  const scene::Panel own = scene::scene_panel(scene);
  const Stage alone(scene, own);
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_EQ(&alone.panel(0), &own);
  expect_same_frames(alone.motion(0), build_motion(scene));
}

TEST(Stage, APanelWithoutAMotionKeepsItsErrorUntilAsked) {
  const scene::Scene scene = pose_panels();
  std::optional<Stage> stage;
  ASSERT_NO_THROW(stage.emplace(scene)) << "made without throwing: a layer may not need the motion";
  EXPECT_NO_THROW((void)stage->motion(0).pose_at<Affine2>(0.5));
  std::string built_alone;
  try {
    (void)build_motion(scene, scene.panels[1]);
  } catch (const NoMotion& error) {
    built_alone = error.what();
  }
  ASSERT_FALSE(built_alone.empty());
  try {
    (void)stage->motion(1);
    ADD_FAILURE() << "no motion expected";
  } catch (const NoMotion& error) {
    EXPECT_EQ(error.what(), built_alone);
    EXPECT_EQ(error.pointer(), "/panels/1/poses");
  }
  EXPECT_THROW(stage->check(), NoMotion);
}

TEST(Stage, APosePanelWithoutPosesHasNoMotionAndPassesTheCheck) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "SAM", "layers": [{"type": "existence"}]})", "e.json");
  const Stage stage(scene);
  ASSERT_EQ(stage.size(), 1u);
  EXPECT_FALSE(stage.has_motion(0));
  EXPECT_NO_THROW(stage.check());
  EXPECT_THROW((void)stage.motion(0), NoMotion);
}

TEST(Stage, DerivedMotionsAreThoseOfThePanelsTheyDescribe) {
  const scene::Scene scene = two_panels();
  const scene::Panel& panel = scene.panels[0];

  scene::Panel p1 = panel;
  track_keys(p1).method = Method::P1;
  expect_same_frames(with_method(scene, panel, Method::P1), build_motion(scene, p1));
  EXPECT_EQ(with_method(scene, panel, Method::P1).method_id(), "P1");

  MethodOptions midpoint = track_keys(panel).options;
  midpoint.anchor = Anchor::midpoint;
  scene::Panel p2 = panel;
  track_keys(p2).method = Method::P2;
  track_keys(p2).options = midpoint;
  EXPECT_EQ(track_keys(layer_panel(panel, Method::P2, midpoint)).method, Method::P2);
  expect_same_frames(with_layer_method(scene, panel, Method::P2, midpoint), build_motion(scene, p2));
  // Without a method of its own, the layer keeps the panel's.
  EXPECT_EQ(with_layer_method(scene, panel, std::nullopt, midpoint).method_id(), "P6");

  // Other keyframes, without the panel's timing.
  const scene::Panel& timed = scene.panels[1];
  std::vector<Keyframe> moved = arrow_keys(timed).keyframes;
  moved[1].arrow.m = 0.9;
  scene::Panel untimed = timed;
  untimed.timing = scene::Timing{};
  arrow_keys(untimed).keyframes = moved;
  const SceneMotion derived = untimed_with_keyframes(scene, timed, moved);
  expect_same_frames(derived, build_motion(scene, untimed));
  EXPECT_EQ(derived.motion_time(0.1), 0.1) << "no warp";
  EXPECT_NE(build_motion(scene, timed).motion_time(0.1), 0.1) << "the panel itself is eased";

  // The scene's keyframes under the timed panel's method and timing.
  scene::Panel reference;
  const SceneMotion base = with_scene_keyframes(scene, timed, &reference);
  EXPECT_EQ(track_keys(reference).method, Method::P8);
  EXPECT_EQ(arrow_keys(reference).keyframes.size(), arrow_keys(scene).keyframes.size());
  expect_same_frames(base, build_motion(scene, timed));  // the same keyframes here
}

TEST(Stage, AnotherPoseMethodThroughThePanelsPoses) {
  const scene::Scene scene = pose_panels();
  const SceneMotion linear = with_method(scene, scene.panels[0], PoseMethod::linear);
  EXPECT_EQ(linear.method_id(), "linear");
  // The linear blend of the matrices at u = 1/2: (I + B) / 2.
  const Affine2 half = linear.pose_at<Affine2>(0.5);
  EXPECT_DOUBLE_EQ(half.L(0, 0), 0.5);
  EXPECT_DOUBLE_EQ(half.L(0, 1), -0.5);
  EXPECT_DOUBLE_EQ(half.b(0), 1.0);
  // The panel without a SAM has a linear motion all the same.
  EXPECT_NO_THROW((void)with_method(scene, scene.panels[1], PoseMethod::linear).pose_at<Affine2>(0.5));
}

}  // namespace
}  // namespace pita::motion
