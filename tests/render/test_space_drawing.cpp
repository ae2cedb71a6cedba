// The geometry of 3D pose scenes (render/space_drawing.hpp): the camera's
// projections against their closed forms, the painter's order, the shading,
// and the faces of a drawn solid against the motion's own poses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "render/space_drawing.hpp"
#include "scene/scene.hpp"

namespace pita::render {
namespace {

using Eigen::Vector3d;

double gap(Point a, Point b) { return std::abs(a - b); }

// Seen from azimuth 0, elevation 0 (on the +x axis, looking towards -x, z
// up), the image's right is +y and its up is +z.
TEST(Projection, OrthographicFromTheXAxis) {
  scene::Camera camera;
  camera.azimuth = 0.0;
  camera.elevation = 0.0;
  camera.distance = 5.0;
  const Projection projection(camera, Vector3d(1, 2, 3));
  EXPECT_LT(gap(*projection.project(Vector3d(1, 2, 3)), Point(0, 0)), 1e-15);
  EXPECT_LT(gap(*projection.project(Vector3d(-7, 3, 3)), Point(1, 0)), 1e-15);  // depth changes nothing
  EXPECT_LT(gap(*projection.project(Vector3d(1, 2, 4.5)), Point(0, 1.5)), 1e-15);
  EXPECT_NEAR(projection.depth(Vector3d(1, 2, 3)), 5.0, 1e-15);
  EXPECT_NEAR(projection.depth(Vector3d(-1, 0, 0)), 7.0, 1e-15);  // farther along -x
}

// Perspective: a point at twice the camera's distance appears half as far
// from the centre; a point behind the camera has no image.
TEST(Projection, PerspectiveDividesByDepth) {
  scene::Camera camera;
  camera.azimuth = 90.0;  // on the +y axis, looking towards -y: right is -x
  camera.elevation = 0.0;
  camera.distance = 4.0;
  camera.perspective = true;
  const Projection projection(camera, Vector3d::Zero());
  EXPECT_LT(gap(*projection.project(Vector3d(-1, 0, 0)), Point(1, 0)), 1e-15);
  EXPECT_LT(gap(*projection.project(Vector3d(-1, -4, 0)), Point(0.5, 0)), 1e-15);
  EXPECT_FALSE(projection.project(Vector3d(0, 5, 0)).has_value());
  camera.distance = 0.0;
  EXPECT_THROW(Projection(camera, Vector3d::Zero()), std::invalid_argument);
}

TEST(Projection, StraightDownKeepsAFrame) {
  scene::Camera camera;
  camera.elevation = 90.0;
  const Projection projection(camera, Vector3d::Zero());
  EXPECT_NEAR(projection.right().norm(), 1.0, 1e-15);
  EXPECT_NEAR(projection.up().norm(), 1.0, 1e-15);
  EXPECT_NEAR(projection.right().dot(projection.forward()), 0.0, 1e-15);
}

TEST(FaceShade, LitFacesAreBrighterThanGrazingOnes) {
  scene::Camera camera;
  const Projection projection(camera, Vector3d::Zero());
  const Vector3d light = (-projection.forward() + 0.8 * projection.up() - 0.5 * projection.right()).normalized();
  EXPECT_NEAR(face_shade(light, projection), 1.0, 1e-15);
  EXPECT_NEAR(face_shade(-light, projection), 1.0, 1e-15);  // either side of a face
  const Vector3d grazing = light.cross(Vector3d(0.3, 0.1, 0.9)).normalized();
  EXPECT_NEAR(face_shade(grazing, projection), 0.35, 1e-15);
}

scene::Scene space_scene(const std::string& layers) {
  return scene::parse_scene(R"({"dimension": 3, "method": "SAM", "shapes": [{"solid": "cube"}],
      "camera": {"azimuth": 0, "elevation": 0, "distance": 10, "target": [0, 0, 0]},
      "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
                {"t": 1, "matrix": [[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0]]}],
      "samples": 2, "layers": )" + layers + "}",
                            "s.json");
}

// Two cubes, at x in [0, 1] and [-3, -2], seen from +x: the far one (x < 0)
// is painted first, each cube's faces back to front, every face filled.
TEST(SpacePanelDrawing, PaintsFarSolidsFirst) {
  const scene::Scene scene = space_scene(R"([{"type": "shapes", "fill": "#808080"}])");
  const Drawing drawing = space_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 12u);  // 2 frames x 6 faces
  for (std::size_t i = 0; i < drawing.items.size(); ++i) {
    ASSERT_TRUE(std::holds_alternative<FilledPath>(drawing.items[i].shape));
    EXPECT_EQ(drawing.items[i].index, i < 6 ? 1 : 0) << i;  // frame 1 (t = 1, the far cube) first
  }
  // The last face painted is the near cube's face x = 1, a unit square on the image.
  const FilledPath& front = std::get<FilledPath>(drawing.items.back().shape);
  ASSERT_EQ(front.contours.size(), 1u);
  double area = 0.0;
  const std::vector<Point>& c = front.contours[0];
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Point a = c[k], b = c[(k + 1) % c.size()];
    area += a.real() * b.imag() - b.real() * a.imag();
  }
  EXPECT_NEAR(std::abs(area) / 2.0, 1.0, 1e-12);
}

// Without a fill, a wireframe: every face's outline, as a closed polyline.
TEST(SpacePanelDrawing, WireframeWithoutFill) {
  const scene::Scene scene = space_scene(R"([{"type": "shapes"}, {"type": "paths", "samples": 5}])");
  const Drawing drawing = space_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 12u + 8u);  // 12 face outlines, 8 vertex paths
  EXPECT_TRUE(std::get<Polyline>(drawing.items[0].shape).closed);
  // The paths are straight here (a translation): vertex (1, 1, 1) moves to (-2, 1, 1), seen at (1, 1) throughout.
  for (std::size_t i = 12; i < drawing.items.size(); ++i) {
    const std::vector<Point>& path = std::get<Polyline>(drawing.items[i].shape).points;
    ASSERT_EQ(path.size(), 5u);
    EXPECT_LT(gap(path.front(), path.back()), 1e-12);
  }
}

// Panels of a 3D scene: each draws its own motion (its poses, or the scene's)
// and its own layers, named by the panel's pointer. Seen from +x, the image's
// right is +y: the panel that translates by 3 along y moves the cube's corner
// (1, 1, 1) from (1, 1) to (4, 1) on the image.
TEST(SpacePanelDrawing, EachPanelDrawsItsOwnPosesAndLayers) {
  const scene::Scene scene = scene::parse_scene(R"({"dimension": 3, "method": "SAM", "shapes": [{"solid": "cube"}],
      "camera": {"azimuth": 0, "elevation": 0, "distance": 10, "target": [0, 0, 0]},
      "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
                {"t": 1, "matrix": [[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0]]}],
      "layers": [{"type": "shapes"}],
      "panels": ["linear", {"title": "along y", "layers": [{"type": "paths", "samples": 2}],
                 "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
                           {"t": 1, "matrix": [[1, 0, 0, 0], [0, 1, 0, 3], [0, 0, 1, 0]]}]}]})",
                                                "s.json");
  ASSERT_EQ(scene.panels.size(), 2u);
  EXPECT_EQ(std::get<scene::SpacePoseKeys>(scene.panels[0].keys).method, PoseMethod::linear);
  EXPECT_EQ(scene.panels[1].title, "along y");
  const Drawing first = space_panel_drawing(scene, scene.panels[0]);
  ASSERT_FALSE(first.items.empty());
  EXPECT_EQ(first.items.front().layer, "/layers/0");  // the scene's layers
  const Drawing second = space_panel_drawing(scene, scene.panels[1]);
  ASSERT_EQ(second.items.size(), 8u);  // a path per vertex of the cube
  bool corner = false;
  for (const Item& item : second.items) {
    EXPECT_EQ(item.layer, "/panels/1/layers/0");
    const std::vector<Point>& path = std::get<Polyline>(item.shape).points;
    ASSERT_EQ(path.size(), 2u);
    EXPECT_LT(std::abs(path.back() - path.front() - Point(3.0, 0.0)), 1e-12);  // its own poses, not the scene's
    corner = corner || gap(path.front(), Point(1.0, 1.0)) < 1e-12;
  }
  EXPECT_TRUE(corner);
}

}  // namespace
}  // namespace pita::render
