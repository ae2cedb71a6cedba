// "camera": {"auto": true} (render/camera_choice.hpp): the openness of a
// posed solid against the closed forms of a cube and a plate, and the
// direction chosen for a plate that the given camera sees edge-on.
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "render/camera_choice.hpp"

namespace pita::render {
namespace {

using Eigen::Vector3d;

// A box of sides a x b x c at the origin, its faces wound outwards.
scene::Solid box_solid(double a, double b, double c) {
  scene::Solid solid;
  for (int i = 0; i < 8; ++i) solid.vertices.emplace_back(a * (i & 1), b * ((i >> 1) & 1), c * ((i >> 2) & 1));
  solid.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return solid;
}

Affine3 unmoved() { return Affine3::identity(); }

TEST(CameraChoice, TowardsEyeFollowsAzimuthAndElevation) {
  EXPECT_LT((towards_eye(0.0, 0.0) - Vector3d::UnitX()).norm(), 1e-15);
  EXPECT_LT((towards_eye(90.0, 0.0) - Vector3d::UnitY()).norm(), 1e-15);
  EXPECT_LT((towards_eye(123.0, 90.0) - Vector3d::UnitZ()).norm(), 1e-15);
}

// A cube's faces show 2 of their 6 unit areas along an axis (1/3), and
// 3 (1/sqrt 3) each, 6/sqrt(3) of 6, along a diagonal.
TEST(CameraChoice, OpennessOfACubeIsItsOutlineOverItsArea) {
  const scene::Solid cube = box_solid(1, 1, 1);
  EXPECT_NEAR(openness(cube, unmoved(), Vector3d::UnitZ()), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(openness(cube, unmoved(), Vector3d(1, 1, 1).normalized()), 1.0 / std::sqrt(3.0), 1e-15);
  // A pose's rotation turns what each direction sees with it.
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Affine3 turned{2.0 * turn, Vector3d(4, 5, 6)};
  const Vector3d d = Vector3d(0.3, -0.5, 0.8).normalized();
  EXPECT_NEAR(openness(cube, turned, turn * d), openness(cube, unmoved(), d), 1e-14);
}

// A 1 x 1 x 0.01 plate: face-on it shows 2 of its 2.04 units, edge-on 0.02.
TEST(CameraChoice, OpennessOfAPlateVanishesEdgeOn) {
  const scene::Solid plate = box_solid(1, 1, 0.01);
  EXPECT_NEAR(openness(plate, unmoved(), Vector3d::UnitZ()), 2.0 / 2.04, 1e-12);
  EXPECT_NEAR(openness(plate, unmoved(), Vector3d::UnitX()), 0.02 / 2.04, 1e-12);
}

// Two plates, upright, one facing x and one facing y, apart: a camera on the x axis
// sees the second edge-on. The chosen direction shows both, and is the given
// one when that one already does.
TEST(CameraChoice, TurnsAwayFromAnEdgeOnPoseAndOtherwiseKeepsTheGivenCamera) {
  const scene::Solid plate = box_solid(0.01, 1, 1);  // facing x
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitZ()).toRotationMatrix();
  // Apart (by 3 along x), so that neither hides the other from 45 degrees.
  const std::vector<Affine3> poses{unmoved(), Affine3{quarter, Vector3d(3, 0, 0)}};
  scene::Camera given;
  given.azimuth = 0.0;
  given.elevation = 10.0;
  given.distance = 7.0;
  given.perspective = true;
  const auto least = [&](const scene::Camera& c) {
    const Vector3d d = towards_eye(c.azimuth, c.elevation);
    return std::min(openness(plate, poses[0], d), openness(plate, poses[1], d));
  };
  ASSERT_LT(least(given), 0.2);
  const scene::Camera chosen = chosen_camera(given, {plate}, poses);
  // The best direction tried sees both plates at 45 degrees, from low down: cos 45 cos 10.
  EXPECT_GT(least(chosen), 0.75 * std::cos(M_PI / 4) * std::cos(kLowestElevation * M_PI / 180) - 1e-9);
  EXPECT_GT(least(chosen), 4.0 * least(given));
  EXPECT_EQ(chosen.distance, 7.0);
  EXPECT_TRUE(chosen.perspective);
  // From 45 degrees the given camera is kept as it is.
  given.azimuth = 45.0;
  given.elevation = 12.5;  // not a direction of the grid
  const scene::Camera kept = chosen_camera(given, {plate}, poses);
  EXPECT_EQ(kept.azimuth, 45.0);
  EXPECT_EQ(kept.elevation, 12.5);
  // Nothing to see: the given camera.
  EXPECT_EQ(chosen_camera(given, {}, poses).azimuth, 45.0);
  EXPECT_EQ(chosen_camera(given, {plate}, {}).azimuth, 45.0);
}

// Two unit cubes seen along z: the farther one wholly behind the nearer (1),
// beside it (0), or shifted by half a side (0.5, to the raster's cell).
TEST(CameraChoice, MostHiddenIsTheShareTheNearerSolidsCover) {
  const scene::Solid cube = box_solid(1, 1, 1);
  const Vector3d up = Vector3d::UnitZ();  // from above: z nearer the eye
  const auto at = [](double x, double y, double z) { return Affine3{Eigen::Matrix3d::Identity(), Vector3d(x, y, z)}; };
  EXPECT_NEAR(most_hidden({cube}, {unmoved(), at(0, 0, 3)}, up), 1.0, 1e-12);
  EXPECT_NEAR(most_hidden({cube}, {unmoved(), at(3, 0, 3)}, up), 0.0, 1e-12);
  EXPECT_NEAR(most_hidden({cube}, {unmoved(), at(0.5, 0, 3)}, up), 0.5, 0.02);
  // One solid, or the same pose twice (a sample at a pose's knot): nothing hidden.
  EXPECT_EQ(most_hidden({cube}, {unmoved()}, up), 0.0);
  EXPECT_EQ(most_hidden({cube}, {unmoved(), unmoved()}, up), 0.0);
}

// Five cubes in a row along x, seen from the x axis: each hides the next.
// The chosen direction shows every one (none hidden by more than
// kMostHidden), and the given one is kept when it does.
TEST(CameraChoice, TurnsAwayFromHiddenPoses) {
  const scene::Solid cube = box_solid(1, 1, 1);
  std::vector<Affine3> row;
  for (int k = 0; k < 5; ++k) row.push_back(Affine3{Eigen::Matrix3d::Identity(), Vector3d(2.0 * k, 0, 0)});
  scene::Camera given;
  given.azimuth = 0.0;
  given.elevation = 10.0;
  ASSERT_GT(most_hidden({cube}, row, towards_eye(given.azimuth, given.elevation)), 0.7);
  const scene::Camera chosen = chosen_camera(given, {cube}, row);
  EXPECT_LE(most_hidden({cube}, row, towards_eye(chosen.azimuth, chosen.elevation)), kMostHidden);
  given.azimuth = 60.0;  // across the row, each cube open enough
  given.elevation = 35.0;
  EXPECT_EQ(chosen_camera(given, {cube}, row).azimuth, 60.0);
  EXPECT_EQ(chosen_camera(given, {cube}, row).elevation, 35.0);
}

}  // namespace
}  // namespace pita::render
