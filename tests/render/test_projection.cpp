// The camera of 3D pose scenes (render/projection.hpp): its projections
// against their closed forms, and the shading of a face.
#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "render/projection.hpp"

namespace pita::render {
namespace {

using Eigen::Vector3d;

double projected_gap(Point a, Point b) { return std::abs(a - b); }

// Seen from azimuth 0, elevation 0 (on the +x axis, looking towards -x, z
// up), the image's right is +y and its up is +z.
TEST(Projection, OrthographicFromTheXAxis) {
  scene::Camera camera;
  camera.azimuth = 0.0;
  camera.elevation = 0.0;
  camera.distance = 5.0;
  const Projection projection(camera, Vector3d(1, 2, 3));
  EXPECT_LT(projected_gap(*projection.project(Vector3d(1, 2, 3)), Point(0, 0)), 1e-15);
  EXPECT_LT(projected_gap(*projection.project(Vector3d(-7, 3, 3)), Point(1, 0)), 1e-15);  // depth changes nothing
  EXPECT_LT(projected_gap(*projection.project(Vector3d(1, 2, 4.5)), Point(0, 1.5)), 1e-15);
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
  EXPECT_LT(projected_gap(*projection.project(Vector3d(-1, 0, 0)), Point(1, 0)), 1e-15);
  EXPECT_LT(projected_gap(*projection.project(Vector3d(-1, -4, 0)), Point(0.5, 0)), 1e-15);
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

}  // namespace
}  // namespace pita::render
