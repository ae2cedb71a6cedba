// Arrow scenes (src/scene/arrow_scene_reader.cpp): keyframes in both forms,
// defaults, samples, options, method names. Refusals: tests/data/bad/.
#include <cmath>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::error_of;
using test::p6_with;
using test::p6_with_middle;

TEST(Scene, ReadsMagnitudeWindingForm) {
  const Scene scene = parse_scene(R"({
    "$schema": "../schema/scene.schema.json",
    "description": "three arrows",
    "method": "P6",
    "keyframes": [
      {"t": 0,   "p": [0, 0],   "m": 1,   "w": 0.4},
      {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
      {"t": 1,   "p": [6, 0],   "m": 1.2, "w": -3.5}
    ]
  })",
                                  "s.json");
  EXPECT_EQ(scene.path, "s.json");
  EXPECT_EQ(scene.description, "three arrows");
  EXPECT_EQ(method_id(scene.keys), "P6");
  EXPECT_EQ(track_keys(scene).method, Method::P6);
  EXPECT_FALSE(scene.samples.has_value());
  ASSERT_EQ(arrow_keys(scene).keyframes.size(), 3u);
  EXPECT_EQ(arrow_keys(scene).keyframes[1].t, 0.5);
  EXPECT_EQ(arrow_keys(scene).keyframes[1].arrow.p, make_point(3, 1.5));
  EXPECT_EQ(arrow_keys(scene).keyframes[1].arrow.m, 0.6);
  EXPECT_EQ(arrow_keys(scene).keyframes[1].arrow.w, 2.0);
  EXPECT_EQ(arrow_keys(scene).keyframes[2].arrow.w, -3.5);  // windings are never reduced
}

TEST(Scene, DefaultsApplied) {
  const Scene scene = parse_scene(p6_with(""), "s.json");
  EXPECT_EQ(scene.description, "");
  EXPECT_FALSE(scene.samples.has_value());
  EXPECT_EQ(track_keys(scene).options.anchor, Anchor::start);
  EXPECT_EQ(track_keys(scene).options.path_mean, MeanKind::geometric);
  EXPECT_EQ(track_keys(scene).options.magnitude_mean, MeanKind::geometric);
}

TEST(Scene, ReadsSamplesAndOptions) {
  // Each option given to a method that reads it (P2 its anchor, SMA its means).
  std::string p2 = p6_with(R"(, "samples": 1000000, "options": {"anchor": "midpoint"})");
  p2.replace(p2.find("\"P6\""), 4, "\"P2\"");
  const Scene scene = parse_scene(p2, "s.json");
  EXPECT_EQ(scene.samples, 1000000);
  EXPECT_EQ(track_keys(scene).options.anchor, Anchor::midpoint);
  const Scene sma = parse_scene(R"({"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 1, "p": [2, 0], "m": 2, "w": 1}], "options": {"path_mean": "arithmetic", "magnitude_mean": "harmonic"}})",
                                "s.json");
  EXPECT_EQ(track_keys(sma).options.path_mean, MeanKind::arithmetic);
  EXPECT_EQ(track_keys(sma).options.magnitude_mean, MeanKind::harmonic);
  EXPECT_EQ(parse_scene(p6_with(R"(, "samples": 2)"), "s.json").samples, 2);
}

TEST(Scene, MethodNamesAreResolvedToCanonicalIds) {
  const std::string keyframes =
      R"("keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [1, 1], "m": 1, "w": 0},
                       {"t": 1, "p": [2, 0], "m": 1, "w": 0}]})";
  const Scene mnemonic = parse_scene(R"({"method": "la-lp", )" + keyframes, "s.json");
  EXPECT_EQ(track_keys(mnemonic).method, Method::P6);
  EXPECT_EQ(method_id(mnemonic.keys), "P6");
  const Scene number = parse_scene(R"({"method": "5s", )" + keyframes, "s.json");
  EXPECT_EQ(method_id(number.keys), "P5S");
}

TEST(Scene, SmaTakesTwoKeyframes) {
  const Scene scene = parse_scene(R"({"method": "SMA", "keyframes": [
    {"t": 0, "p": [0, 0], "m": 2, "w": 0.3}, {"t": 1, "p": [4, 1], "m": 0.5, "w": 4.3}]})",
                                  "s.json");
  EXPECT_EQ(track_keys(scene).method, Method::SMA);
  EXPECT_EQ(arrow_keys(scene).keyframes.size(), 2u);
}

// ------------------------------------------------------------ handles and shapes
// PITA Sec. 7.1: "shapes" carried by the frames, drawn in the frame of the
// "handle" (default: the first keyframe); moving keyframes (Sec. 7.4).

TEST(Scene, HandleAndShapesAreRead) {
  const Scene scene =
      parse_scene(p6_with(R"(, "handle": {"p": [5, 5], "q": [5, 7]}, "shapes": [{"outline": "square", "color": "red"}],
                 "layers": [{"type": "shapes", "fill": "blue"}, {"type": "handle", "width": 3, "shapes": false}])"),
                  "s.json");
  ASSERT_TRUE(arrow_keys(scene).given_handle.has_value());
  EXPECT_EQ(arrow_keys(scene).given_handle->p, make_point(5, 5));
  EXPECT_EQ(arrow_keys(scene).given_handle->m, 2.0);
  ASSERT_EQ(figure_of<KeyframeKeys>(scene).shapes.size(), 1u);
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).shapes[0].points.size(), 4u);
  ASSERT_EQ(scene.panels.size(), 1u);
  EXPECT_EQ(arrow_keys(scene.panels[0]).handle().p, make_point(5, 5));
  EXPECT_EQ(figure_of<KeyframeKeys>(scene.panels[0]).shapes.size(), 1u);
  ASSERT_EQ(figure_of<KeyframeKeys>(scene).layers.size(), 2u);
  ASSERT_TRUE(std::holds_alternative<ShapesLayer>(figure_of<KeyframeKeys>(scene).layers[0]));
  EXPECT_TRUE(std::get<ShapesLayer>(figure_of<KeyframeKeys>(scene).layers[0]).fill.has_value());
  ASSERT_TRUE(std::holds_alternative<HandleLayer>(figure_of<KeyframeKeys>(scene).layers[1]));
  EXPECT_EQ(std::get<HandleLayer>(figure_of<KeyframeKeys>(scene).layers[1]).width, 3.0);
  EXPECT_FALSE(std::get<HandleLayer>(figure_of<KeyframeKeys>(scene).layers[1]).shapes);
}

TEST(Scene, HandleDefaultsToTheFirstKeyframe) {
  const Scene scene = parse_scene(p6_with(R"(, "shapes": [{"outline": "F"}])"), "s.json");
  EXPECT_FALSE(arrow_keys(scene).given_handle.has_value());
  ASSERT_EQ(scene.panels.size(), 1u);
  EXPECT_EQ(arrow_keys(scene.panels[0]).handle().p, arrow_keys(scene).keyframes[0].arrow.p);
  EXPECT_EQ(arrow_keys(scene.panels[0]).handle().m, arrow_keys(scene).keyframes[0].arrow.m);
  EXPECT_EQ(arrow_keys(scene.panels[0]).handle().w, arrow_keys(scene).keyframes[0].arrow.w);
  // Arrow scenes have no shapes unless they give them (pose scenes default to
  // the reference triangle).
  EXPECT_TRUE(figure_of<KeyframeKeys>(parse_scene(p6_with(""), "s.json")).shapes.empty());
}

TEST(Scene, MovingKeyframesGiveTargetsToEveryPanel) {
  const Scene scene = parse_scene(R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 0.5, "from": {"p": [1, 1], "m": 1, "w": 0}, "to": {"p": [1, -1], "m": 2, "w": 1}},
      {"t": 1, "p": [2, 0], "m": 1, "w": 0}], "panels": ["P2", {"title": "same"}]})",
                                  "s.json");
  ASSERT_EQ(arrow_keys(scene).keyframes_to.size(), 3u);
  EXPECT_EQ(arrow_keys(scene).keyframes[1].arrow.p, make_point(1, 1));  // "from"
  EXPECT_EQ(arrow_keys(scene).keyframes_to[1].p, make_point(1, -1));    // "to"
  EXPECT_EQ(arrow_keys(scene).keyframes_to[0].p, arrow_keys(scene).keyframes[0].arrow.p);
  for (const Panel& panel : scene.panels) {
    ASSERT_EQ(arrow_keys(panel).keyframes_to.size(), 3u) << panel.pointer;
    EXPECT_EQ(arrow_keys(panel).keyframes_to[1].m, 2.0) << panel.pointer;
  }
  EXPECT_TRUE(arrow_keys(parse_scene(p6_with(""), "s.json")).keyframes_to.empty());
}

TEST(Scene, ShapesLayersNeedShapes) {
  EXPECT_EQ(error_of(p6_with(R"(, "layers": [{"type": "pattern"}, {"type": "shapes"}])")),
            "s.json: /layers/1/type: a \"shapes\" layer draws the scene's \"shapes\" carried by the handle, and the "
            "scene has none");
  EXPECT_EQ(error_of(p6_with(R"(, "panels": ["P2", {"layers": [{"type": "shapes"}]}])")),
            "s.json: /panels/1/layers/0/type: a \"shapes\" layer draws the scene's \"shapes\" carried by the "
            "handle, and the scene has none");
  // A handle layer draws the handle alone when there are no shapes.
  EXPECT_EQ(error_of(p6_with(R"(, "layers": [{"type": "handle"}])")), "(no error)");
  EXPECT_EQ(error_of(p6_with(R"(, "shapes": [{"outline": "F"}], "layers": [{"type": "shapes"}])")), "(no error)");
}

TEST(Scene, HandlesNeedKeyframes) {
  const std::string points =
      R"([{"t": 0, "p": [0, 0]}, {"t": 1, "p": [1, 1]}, {"t": 2, "p": [2, 0]}, {"t": 3, "p": [3, 1]}])";
  EXPECT_EQ(error_of(R"({"method": "P6", "points": )" + points + R"(, "handle": {"p": [0, 0], "q": [1, 0]}})"),
            "s.json: /handle: a handle carries shapes with keyframe arrows; a scene of \"points\" has none");
  EXPECT_EQ(error_of(p6_with(R"(, "handle": {"p": [1, 1], "q": [1, 1]})")),
            "s.json: /handle/q: q equals p: a zero-length arrow has no direction");
}

// ------------------------------------------------------------ bad scenes
//
// Every bad scene is a file of tests/data/bad/ with the pointer (or line and
// column) and the reason it must give: tests/scene/test_bad_scenes.cpp runs
// them. Here: the parts of SceneError, and the limits' good side.

}  // namespace
}  // namespace pita::scene
