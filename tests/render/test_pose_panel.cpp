// A panel of a pose scene as its layers see it (render/pose_panel.hpp), in
// the plane and in space: the body's points, the camera's image, the
// velocity per unit of normalised time, and the errors it names.
#include <cmath>
#include <string>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "motion/stage.hpp"
#include "render/pose_panel.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

// A unit cube translated by (-3, 0, 0) from t = 0 to t = 2, seen from +x.
scene::Scene moving_cube(const std::string& camera) {
  return scene::parse_scene(R"({"dimension": 3, "method": "linear", "shapes": [{"solid": "cube"}],
      "camera": )" + camera + R"(,
      "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
                {"t": 2, "matrix": [[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0]]}]})",
                            "cube.json");
}

constexpr const char* kFromX = R"({"azimuth": 0, "elevation": 0, "distance": 10, "target": [0, 0, 0]})";

// dA/du with u = (t - 0) / 2: the translation by -3 over the whole motion, in
// space as in the plane (the "velocities" layer's scale multiplies it).
TEST(PosePanel, VelocityIsPerUnitOfNormalisedTime) {
  const scene::Scene scene = moving_cube(kFromX);
  const motion::Stage stage(scene);
  const PosePanel<Affine3> panel(stage, 0, nullptr);
  for (const double t : {0.0, 0.5, 1.7}) {
    const Affine3 rate = panel.velocity_at(t);
    EXPECT_LT((rate.b - Eigen::Vector3d(-3.0, 0.0, 0.0)).norm(), 1e-12) << t;
    EXPECT_LT(rate.L.norm(), 1e-12) << t;
    EXPECT_LT((panel.pose_at(t).b - Eigen::Vector3d(-1.5 * t, 0.0, 0.0)).norm(), 1e-12) << t;
  }
}

// The body of a 3D panel is every vertex of every solid, in order; seen from
// +x, the image's right is +y and its up is +z.
TEST(PosePanel, SpaceBodyIsTheSolidsVerticesThroughTheCamera) {
  const scene::Scene scene = moving_cube(kFromX);
  const motion::Stage stage(scene);
  const PosePanel<Affine3> panel(stage, 0, nullptr);
  ASSERT_EQ(scene::figure_of<scene::SpacePoseKeys>(scene).shapes.size(), 1u);
  const auto points = panel.body_points();
  ASSERT_EQ(points.size(), scene::figure_of<scene::SpacePoseKeys>(scene).shapes[0].vertices.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_EQ(points[k], scene::figure_of<scene::SpacePoseKeys>(scene).shapes[0].vertices[k]);
    EXPECT_LT(std::abs(panel.image(points[k]) - Point(points[k].y(), points[k].z())), 1e-12);
  }
}

// A point behind a perspective camera has no image: the error names the
// camera's distance.
TEST(PosePanel, PointBehindThePerspectiveCameraIsRefused) {
  const scene::Scene scene =
      moving_cube(R"({"azimuth": 0, "elevation": 0, "distance": 4, "projection": "perspective", "target": [0, 0, 0]})");
  const motion::Stage stage(scene);
  const PosePanel<Affine3> panel(stage, 0, nullptr);
  try {
    (void)panel.image(Eigen::Vector3d(5.0, 0.0, 0.0));
    FAIL() << "no error";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("cube.json: /camera/distance: a point of the figure (5, 0, 0) is behind"),
              std::string::npos)
        << error.what();
  }
}

// A panel of another kind (poses of space asked for as poses of the plane)
// is refused at the panel, not misread.
TEST(PosePanel, PanelOfAnotherKindIsRefused) {
  const scene::Scene scene = moving_cube(kFromX);
  const motion::Stage stage(scene);
  EXPECT_THROW(PosePanel<Affine2>(stage, 0, nullptr), RenderError);
}

// In the plane the body is every point of every shape, drawn where it is.
TEST(PosePanel, PlaneBodyIsTheShapesPoints) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "SAM",
      "shapes": [{"polygon": [[0, 0], [1, 0], [0, 1]]}, {"polyline": [[2, 2], [3, 2]]}],
      "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[1, 0, 1], [0, 1, 0]]}]})",
                                                "plane.json");
  const motion::Stage stage(scene);
  const PosePanel<Affine2> panel(stage, 0, nullptr);
  const std::vector<Point> points = panel.body_points();
  const std::vector<Point> expected = {{0, 0}, {1, 0}, {0, 1}, {2, 2}, {3, 2}};
  EXPECT_EQ(points, expected);
  EXPECT_EQ(panel.image(Point(2.5, -1.0)), Point(2.5, -1.0));
}

}  // namespace
}  // namespace pita::render
