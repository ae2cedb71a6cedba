// Pose scenes (src/scene/pose_scene_reader.cpp): which documents are pose
// scenes, their defaults, and that a pose scene without poses may still draw
// layers that need none.
#include <string>

#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene/scene_readers.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

TEST(PoseSceneReader, PoseScenesAreRecognisedByPosesOrAPoseMethod) {
  EXPECT_TRUE(detail::is_pose_scene(detail::Json::parse(R"({"poses": []})")));
  EXPECT_TRUE(detail::is_pose_scene(detail::Json::parse(R"({"method": "polysam"})")));
  EXPECT_FALSE(detail::is_pose_scene(detail::Json::parse(R"({"method": "SAM", "keyframes": []})")));
  EXPECT_FALSE(detail::is_pose_scene(detail::Json::parse(R"({"method": "P6"})")));
}

TEST(PoseSceneReader, DefaultsApplied) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "triangle": [[1, 0], [2, 0], [1, 1]]}]})",
                                  "s.json");
  EXPECT_TRUE(std::holds_alternative<PlanePoseKeys>(scene.keys));
  EXPECT_EQ(method_id(scene.keys), "SAM");
  ASSERT_EQ(figure_of<PlanePoseKeys>(scene).shapes.size(), 1u);  // the reference triangle
  EXPECT_EQ(figure_of<PlanePoseKeys>(scene).shapes[0].points.size(), 3u);
  ASSERT_EQ(figure_of<PlanePoseKeys>(scene).layers.size(), 2u);  // shapes, then poses
  EXPECT_TRUE(std::holds_alternative<ShapesLayer>(figure_of<PlanePoseKeys>(scene).layers[0]));
  EXPECT_TRUE(std::holds_alternative<PosesLayer>(figure_of<PlanePoseKeys>(scene).layers[1]));
  EXPECT_EQ(plane_keys(scene).subdivisions, kDefaultSubdivisions);
  EXPECT_EQ(plane_keys(scene).poses[1].pose.b,
            Eigen::Vector2d(1.0, 0.0));  // triangle pose: the translation moves (0, 0) to (1, 0)
  ASSERT_EQ(scene.panels.size(), 1u);
  EXPECT_EQ(scene.panels[0].motion_pointer, "/poses");
}

TEST(PoseSceneReader, LayersThatNeedNoPosesNeedNoPoses) {
  EXPECT_NO_THROW(parse_scene(
      R"({"method": "SAM", "layers": [{"type": "existence"}, {"type": "label", "text": "x", "at": [0, 0]}]})",
      "s.json"));
  EXPECT_THROW(parse_scene(R"({"method": "SAM", "layers": [{"type": "shapes"}]})", "s.json"), SceneError);
  EXPECT_TRUE(detail::needs_motion({ShapesLayer{}}));
  EXPECT_TRUE(detail::needs_motion({PlotLayer{}}));
  EXPECT_FALSE(detail::needs_motion({ExistenceLayer{}, LabelLayer{}, PatchLayer{}, Sam3dExistenceLayer{}}));
  EXPECT_NO_THROW(parse_scene(R"({"method": "SAM", "layers": [{"type": "sam3d-existence"}]})", "s.json"));
}

TEST(PoseSceneReader, Sam3dExistenceLayerFields) {
  const Scene scene = parse_scene(R"({"method": "SAM", "layers": [{"type": "sam3d-existence", "steps": 12,
      "subdivisions": 1, "step": 0.02, "color": "#ff0000", "fill": "none", "paper": {"width": 3}}]})",
                                  "s.json");
  const auto& layer = std::get<Sam3dExistenceLayer>(figure_of<PlanePoseKeys>(scene).layers.at(0));
  EXPECT_EQ(layer.steps, 12);
  EXPECT_EQ(layer.subdivisions, 1);
  EXPECT_DOUBLE_EQ(layer.step, 0.02);
  EXPECT_DOUBLE_EQ(layer.line.color.r, 1.0);
  EXPECT_FALSE(layer.fill.has_value());
  EXPECT_TRUE(layer.paper);
  EXPECT_DOUBLE_EQ(layer.paper_line.width, 3.0);
  const Scene defaults =
      parse_scene(R"({"method": "SAM", "layers": [{"type": "sam3d-existence", "paper": false}]})", "s.json");
  const auto& plain = std::get<Sam3dExistenceLayer>(figure_of<PlanePoseKeys>(defaults).layers.at(0));
  EXPECT_EQ(plain.steps, 48);
  EXPECT_EQ(plain.subdivisions, 2);
  EXPECT_TRUE(plain.fill.has_value());
  EXPECT_FALSE(plain.paper);
}

}  // namespace
}  // namespace pita::scene
