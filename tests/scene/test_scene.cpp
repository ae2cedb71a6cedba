// Scene parsing (src/scene/scene.cpp): the parts of SceneError, method
// overrides, files. Arrow scenes are read by arrow_scene_reader.cpp
// (test_arrow_scene_reader.cpp), pose scenes by pose_scene_reader.cpp, panels
// by panel_reader.cpp, the text by json_text.cpp. Keyframes are read by
// json_reader.cpp (test_json_reader.cpp), poses by pose_reader.cpp
// (test_pose_reader.cpp). The bad scenes are files of tests/data/bad/,
// run by test_bad_scenes.cpp. Every error test asserts the whole message: file,
// JSON Pointer and reason.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <variant>

#include <gtest/gtest.h>
#include <unistd.h>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::p6_with;
using test::p6_with_middle;

// ------------------------------------------------------------ good scenes

TEST(SceneError, ErrorCarriesItsParts) {
  try {
    parse_scene("{\n\n  ]", "s.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.file(), "s.json");
    EXPECT_EQ(error.line(), 3);
    EXPECT_EQ(error.column(), 3);
    EXPECT_EQ(error.pointer(), "");
  }
  try {
    parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": -2, "w": 1})"), "s.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/keyframes/1/m");
    EXPECT_EQ(error.reason(), "magnitude must be > 0 (got -2)");
    EXPECT_EQ(error.line(), 0);
  }
}

// ------------------------------------------------------------ methods and files

TEST(Scene, ResolveMethod) {
  EXPECT_EQ(resolve_method("P8"), Method::P8);
  EXPECT_EQ(resolve_method("lo-pe"), Method::P8);
  try {
    resolve_method("P66");
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()).rfind("unknown method \"P66\"; did you mean P6 (La-LP)", 0), 0u)
        << error.what();
  }
}

TEST(Scene, WithMethodReplacesTheMethodWhenTheCountFits) {
  const Scene scene = with_method(parse_scene(p6_with(""), "s.json"), Method::P8);
  EXPECT_EQ(track_keys(scene).method, Method::P8);
  EXPECT_EQ(method_id(scene.keys), "P8");
  try {
    with_method(parse_scene(p6_with(R"(, "chain": "blend")"), "s.json"), Method::SMA);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("s.json: /chain: chain \"blend\" blends a method through three"),
              std::string::npos)
        << error.what();
  }
}

TEST(Scene, LoadSceneReportsUnreadableFiles) {
  try {
    load_scene("no/such/scene.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_STREQ(error.what(), "no/such/scene.json: cannot open the scene file (No such file or directory)");
  }
  try {
    load_scene(std::filesystem::temp_directory_path());
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.reason(), "cannot read the scene file: it is a directory");
  }
}

TEST(Scene, LoadSceneNamesTheFileAsGiven) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("pita-test-scene-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({"method": "P6", "keyframes": []})";
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() +
                  ": /keyframes: method P6 (La-LP) takes at least 3 keyframes (got 0); more are chained "
                  "(\"chain\")");
  }
  std::filesystem::remove(path);
}

// ------------------------------------------------------------ pose scenes
//
// What the scene makes of its pose panels and method overrides; reading the
// poses themselves is test_pose_reader.cpp.

TEST(PoseScene, MethodOverride) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0, -1, 2], [1, 0, 2]]}]})",
                                  "s.json");
  EXPECT_EQ(method_id(with_method(scene, PoseMethod::linear).keys), "linear");
  EXPECT_THROW(with_method(scene, PoseMethod::biarc_sam), SceneError);  // 3 poses
  EXPECT_THROW(with_method(scene, Method::P6), SceneError);
}

// ------------------------------------------------------------ figure data

// Each kind's figure data is of its keys' family: arrows (keyframes and
// points), poses of the plane, poses of space; figure_of takes the family
// from the keys' type.
TEST(SceneFigure, EachKindHoldsTheFigureOfItsFamily) {
  const Scene arrows = parse_scene(p6_with(""), "s.json");
  EXPECT_TRUE(figure_agrees(arrows.keys, arrows.figure));
  EXPECT_EQ(figure_of<KeyframeKeys>(arrows).layers.size(), 2u);  // pattern, keyframes
  EXPECT_TRUE(figure_of<KeyframeKeys>(arrows.panels[0]).shapes.empty());
  const Scene plane = parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -1, 1], [1, 0, 0]]}]})",
                                  "s.json");
  const PoseFigure<Affine2>& flat = figure_of<PlanePoseKeys>(plane);
  EXPECT_EQ(flat.reference[1], Point(1.0, 0.0));
  ASSERT_EQ(flat.shapes.size(), 1u);  // the reference triangle
  EXPECT_EQ(figure_of(plane.panels[0], std::get<PlanePoseKeys>(plane.panels[0].keys)).shapes.size(), 1u);
  const Scene space = parse_scene(R"({"dimension": 3, "method": "SAM", "camera": {"azimuth": 10},
      "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
                {"t": 1, "matrix": [[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0]]}]})",
                                  "s.json");
  const PoseFigure<Affine3>& solid = figure_of<SpacePoseKeys>(space);
  EXPECT_EQ(solid.camera.azimuth, 10.0);
  ASSERT_EQ(solid.shapes.size(), 1u);  // the reference tetrahedron
  EXPECT_EQ(solid.shapes[0].vertices.size(), 4u);
  // A space panel draws the scene's solids; it has no outlines of the plane.
  EXPECT_EQ(figure_of<SpacePoseKeys>(space.panels[0]).shapes.size(), 1u);
  EXPECT_TRUE(outlines_of(space.panels[0]).empty());
  EXPECT_EQ(outlines_of(plane.panels[0]).size(), 1u);
  // Another family's figure is refused, not reinterpreted.
  EXPECT_FALSE(figure_agrees(plane.keys, arrows.figure));
  EXPECT_FALSE(figure_agrees(space.keys, plane.panels[0].figure));
  EXPECT_THROW((void)figure_of<PlanePoseKeys>(arrows), std::bad_variant_access);
}

// A panel of points in a scene of keyframes is of the same family: it draws
// the scene's arrow layers.
TEST(SceneFigure, PointPanelsOfAKeyframeSceneShareItsFigure) {
  const Scene scene = parse_scene(p6_with(R"(, "layers": [{"type": "label", "text": "x", "at": [0, 0]}],
      "panels": [{"points": [{"t": 0, "p": [0, 0]}, {"t": 1, "p": [1, 0]}, {"t": 2, "p": [1, 1]},
                             {"t": 3, "p": [0, 1]}]}])"),
                                  "s.json");
  ASSERT_TRUE(std::holds_alternative<PointKeys>(scene.panels[0].keys));
  EXPECT_TRUE(figure_agrees(scene.panels[0].keys, scene.panels[0].figure));
  const LayersOf<Layer> drawn = layers_of<Layer>(scene, scene.panels[0]);
  EXPECT_FALSE(drawn.own);
  EXPECT_EQ(drawn.layers.size(), 1u);
  EXPECT_THROW((void)layers_of<PoseLayer>(scene, scene.panels[0]), std::logic_error);
}

// The points a pose moves: an outline's points, a solid's vertices.
TEST(SceneFigure, PointsOfAShape) {
  const ShapeOutline outline{{Point{0.0, 0.0}, Point{1.0, 2.0}}, false, std::nullopt, std::nullopt};
  EXPECT_EQ(points_of(outline).size(), 2u);
  Solid solid;
  solid.vertices = {Eigen::Vector3d(1, 2, 3)};
  EXPECT_EQ(points_of(solid).front(), Eigen::Vector3d(1, 2, 3));
}

}  // namespace
}  // namespace pita::scene
