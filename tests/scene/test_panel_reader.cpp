// Panels (src/scene/panel_reader.cpp): what a panel inherits from the scene
// and what it overrides, for arrow and pose scenes, and the pointer its
// motion's errors name.
#include <string>

#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::kKeyframes;

TEST(PoseScene, PanelsInheritAndOverride) {
  const Scene scene = parse_scene(R"({"method": "polySAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0, -1, 2], [1, 0, 2]]},
      {"t": 2, "matrix": [[-1, 0, 4], [0, -1, 0]]}],
      "panels": ["linear", {"method": "biarc-SAM", "samples": 5},
                 {"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
                                             {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}]}]})",
                                  "s.json");
  ASSERT_EQ(scene.panels.size(), 3u);
  EXPECT_EQ(pose_method_of(scene.panels[0]), PoseMethod::linear);
  EXPECT_EQ(plane_keys(scene.panels[0]).poses.size(), 3u);
  EXPECT_EQ(pose_method_of(scene.panels[1]), PoseMethod::biarc_sam);
  EXPECT_EQ(scene.panels[1].samples, 5);
  EXPECT_EQ(plane_keys(scene.panels[2]).poses.size(), 2u);
  EXPECT_EQ(scene.panels[2].title, "SAM");
}

TEST(PanelReader, ArrowPanelsInheritAndOverride) {
  const Scene scene =
      parse_scene(R"({"method": "P9", "options": {"anchor": "midpoint", "path_mean": "harmonic"}, "samples": 5, )" +
                      kKeyframes + R"(,
      "panels": ["P2", {"method": "P3", "title": "three", "samples": 7},
                 {"options": {"magnitude_mean": "arithmetic"}},
                 {"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 2, "p": [1, 0], "m": 1, "w": 1}]}]})",
                  "s.json");
  ASSERT_EQ(scene.panels.size(), 4u);
  EXPECT_EQ(track_keys(scene.panels[0]).method, Method::P2);
  EXPECT_EQ(scene.panels[0].title, "P2 LS-Po");
  EXPECT_EQ(scene.panels[0].samples, 5);
  EXPECT_EQ(track_keys(scene.panels[0]).options.anchor, track_keys(scene).options.anchor);
  EXPECT_EQ(scene.panels[1].title, "three");
  EXPECT_EQ(scene.panels[1].samples, 7);
  // Each option read by a motion it applies to: the anchor by panel 0 (P2),
  // the means by the scene's P9 and panel 2, which inherits it.
  EXPECT_EQ(track_keys(scene.panels[2]).method, Method::P9);
  EXPECT_EQ(track_keys(scene.panels[2]).options.magnitude_mean, MeanKind::arithmetic);
  EXPECT_EQ(track_keys(scene.panels[2]).options.path_mean,
            track_keys(scene).options.path_mean);  // the fields not given stay the scene's
  EXPECT_EQ(track_keys(scene.panels[2]).options.path_mean, MeanKind::harmonic);
  EXPECT_EQ(arrow_keys(scene.panels[3]).keyframes.size(), 2u);
  EXPECT_EQ(scene.panels[3].pointer, "/panels/3");
}

TEST(PanelReader, MotionPointerNamesWhatTheMotionIsBuiltFrom) {
  const Scene scene = parse_scene(R"({"method": "P6", )" + kKeyframes + R"(,
      "panels": ["P1", {"title": "same"}, {"method": "P8"}, {"keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
        {"t": 1, "p": [1, 1], "m": 1, "w": 0}, {"t": 2, "p": [2, 0], "m": 1, "w": 0}]}]})",
                                  "s.json");
  EXPECT_EQ(scene.panels[0].motion_pointer, "/panels/0");   // its method, the scene's keyframes
  EXPECT_EQ(scene.panels[1].motion_pointer, "/keyframes");  // the scene's motion
  EXPECT_EQ(scene.panels[2].motion_pointer, "/panels/2");
  EXPECT_EQ(scene.panels[3].motion_pointer, "/panels/3/keyframes");  // its own keyframes
  const Scene poses = parse_scene(R"({"method": "polySAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[1, 0, 2], [0, 1, 0]]}], "panels": ["SAM", {"title": "x"},
      {"poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}]}]})",
                                  "s.json");
  EXPECT_EQ(poses.panels[0].motion_pointer, "/panels/0");
  EXPECT_EQ(poses.panels[1].motion_pointer, "/poses");
  EXPECT_EQ(poses.panels[2].motion_pointer, "/panels/2/poses");
}

// A panel's handle (PITA Sec. 7.1): its own "handle", else the scene's, else
// the panel's first keyframe ("from" when it moves).
TEST(PanelReader, HandleDefaultsToTheScenesThenToThePanelsFirstKeyframe) {
  const std::string panels = R"(, "panels": ["P2",
      {"keyframes": [{"t": 0, "from": {"p": [7, 7], "m": 3, "w": 1}, "to": {"p": [8, 8], "m": 3, "w": 1}},
                     {"t": 1, "p": [1, 1], "m": 1, "w": 0}, {"t": 2, "p": [2, 0], "m": 1, "w": 0}]},
      {"handle": {"p": [4, 4], "m": 0.5, "w": 2}},
      {"handle": {"p": [4, 4], "m": 0.5, "w": 2}, "keyframes": [{"t": 0, "p": [9, 9], "m": 1, "w": 0},
                     {"t": 1, "p": [1, 1], "m": 1, "w": 0}, {"t": 2, "p": [2, 0], "m": 1, "w": 0}]}])";
  const std::string keyframes = R"("keyframes": [{"t": 0, "p": [-1, 0], "m": 1.5, "w": 0.25},
    {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}])";

  // The scene has no handle.
  const Scene scene = parse_scene(R"({"method": "P6", )" + keyframes + panels + "}", "s.json");
  ASSERT_EQ(scene.panels.size(), 4u);
  EXPECT_EQ(arrow_keys(scene.panels[0]).handle().p, make_point(-1, 0));  // the scene's first keyframe
  EXPECT_EQ(arrow_keys(scene.panels[0]).handle().m, 1.5);
  EXPECT_EQ(arrow_keys(scene.panels[0]).handle().w, 0.25);
  EXPECT_EQ(arrow_keys(scene.panels[1]).handle().p, make_point(7, 7));  // the panel's first keyframe, "from"
  EXPECT_EQ(arrow_keys(scene.panels[1]).handle().m, 3.0);
  EXPECT_EQ(arrow_keys(scene.panels[2]).handle().p, make_point(4, 4));  // its own
  EXPECT_EQ(arrow_keys(scene.panels[2]).handle().w, 2.0);
  EXPECT_EQ(arrow_keys(scene.panels[3]).handle().p, make_point(4, 4));  // its own, over its keyframes
  ASSERT_EQ(arrow_keys(scene.panels[1]).keyframes_to.size(), 3u);
  EXPECT_EQ(arrow_keys(scene.panels[1]).keyframes_to[0].p, make_point(8, 8));
  EXPECT_TRUE(arrow_keys(scene.panels[0]).keyframes_to.empty());

  // The scene's handle is every panel's that gives none, whatever its keyframes.
  const Scene handled =
      parse_scene(R"({"method": "P6", "handle": {"p": [0, 5], "q": [1, 5]}, )" + keyframes + panels + "}", "s.json");
  EXPECT_EQ(arrow_keys(handled.panels[0]).handle().p, make_point(0, 5));
  EXPECT_EQ(arrow_keys(handled.panels[1]).handle().p, make_point(0, 5));
  EXPECT_EQ(arrow_keys(handled.panels[1]).handle().m, 1.0);
  EXPECT_EQ(arrow_keys(handled.panels[2]).handle().p, make_point(4, 4));
  EXPECT_EQ(arrow_keys(handled.panels[3]).handle().p, make_point(4, 4));

  // Not over points.
  EXPECT_EQ(test::error_of(R"({"method": "P6", )" + keyframes + R"(, "panels": [{"points": [{"t": 0, "p": [0, 0]},
      {"t": 1, "p": [1, 1]}, {"t": 2, "p": [2, 0]}, {"t": 3, "p": [3, 1]}], "handle": {"p": [0, 0], "q": [1, 0]}}]})"),
            "s.json: /panels/0/handle: a handle carries shapes with keyframe arrows; this panel has \"points\"");
}

}  // namespace
}  // namespace pita::scene
