// The points of the body a pose panel moves (src/scene/body_points.cpp): one
// rule for the figure's layers and pita measure's ARA.
#include <gtest/gtest.h>

#include <vector>

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
  bare.shapes.clear();
  EXPECT_EQ(body_points<Affine2>(scene, bare),
            std::vector<Point>(scene.reference_triangle.begin(), scene.reference_triangle.end()));
}

// In space: every vertex of every solid of the scene; by default the
// reference tetrahedron's solid, and the tetrahedron itself without solids.
TEST(BodyPoints, SpaceBodyIsTheSolidsVertices) {
  Scene scene = parse_scene(R"({"dimension": 3, "method": "SAM", "shapes": [{"solid": "cube"}], "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]]}]})",
                            "space.json");
  const Panel panel = scene_panel(scene);
  ASSERT_EQ(scene.solids.size(), 1u);
  EXPECT_EQ(body_points<Affine3>(scene, panel), scene.solids[0].vertices);
  EXPECT_EQ(body_points<Affine3>(scene, panel).size(), 8u);
  scene.solids.clear();
  EXPECT_EQ(body_points<Affine3>(scene, panel),
            std::vector<Eigen::Vector3d>(scene.reference_tetrahedron.begin(), scene.reference_tetrahedron.end()));
}

}  // namespace
}  // namespace pita::scene
