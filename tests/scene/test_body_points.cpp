// The points of the body a pose panel moves (src/scene/body_points.cpp): one
// rule for the figure's layers and pita measure's ARA.
#include <vector>

#include <gtest/gtest.h>

#include "scene/body_points.hpp"
#include "scene/scene.hpp"

namespace pita::scene {
namespace {

// In the plane: every point of every shape of the panel, in order.
TEST(BodyPoints, PlaneBodyIsThePanelsShapesPoints) {
  const Scene scene = parse_scene(R"({"method": "SAM",
      "shapes": [{"polygon": [[0, 0], [1, 0], [0, 1]]}, {"polyline": [[2, 2], [3, 2]]}],
      "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[1, 0, 1], [0, 1, 0]]}]})",
                                  "plane.json");
  const Panel panel = scene_panel(scene);
  EXPECT_EQ(body_points<Affine2>(scene, panel), (std::vector<Point>{{0, 0}, {1, 0}, {0, 1}, {2, 2}, {3, 2}}));
  // Without shapes (a scene the readers never give): the reference triangle.
  Panel bare = panel;
  figure_of<PlanePoseKeys>(bare).shapes.clear();
  const auto& reference = figure_of<PlanePoseKeys>(scene).reference;
  EXPECT_EQ(body_points<Affine2>(scene, bare), std::vector<Point>(reference.begin(), reference.end()));
}

// In space: every vertex of every solid the panel draws (the scene's); by
// default the reference tetrahedron's solid, and the tetrahedron itself
// without solids.
TEST(BodyPoints, SpaceBodyIsTheSolidsVertices) {
  const Scene scene = parse_scene(R"({"dimension": 3, "method": "SAM", "shapes": [{"solid": "cube"}], "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]]}]})",
                                  "space.json");
  Panel panel = scene_panel(scene);
  const auto& solids = figure_of<SpacePoseKeys>(scene).shapes;
  ASSERT_EQ(solids.size(), 1u);
  EXPECT_EQ(body_points<Affine3>(scene, panel), solids[0].vertices);
  EXPECT_EQ(body_points<Affine3>(scene, panel).size(), 8u);
  figure_of<SpacePoseKeys>(panel).shapes.clear();
  const auto& reference = figure_of<SpacePoseKeys>(scene).reference;
  EXPECT_EQ(body_points<Affine3>(scene, panel), std::vector<Eigen::Vector3d>(reference.begin(), reference.end()));
}

}  // namespace
}  // namespace pita::scene
