// Reading 3D pose scenes (src/scene/space_pose_reader.cpp; docs/reference/pose-scenes.md "3D pose
// scenes"): 3x4 matrices and tetrahedra, the reference tetrahedron, which
// commands may read them. Refusals: tests/data/bad/space-*; the schema side:
// test_schema.cpp (SpaceScenesAgreeWithTheParser).
#include <string>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene/space_pose_reader.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using Eigen::Vector3d;

Scene parse_space(const std::string& text) { return parse_scene(text, "s.json"); }

TEST(SpacePoseScene, MatricesAreRowsOfTheAffinity) {
  const Scene scene = parse_space(R"({"dimension": 3, "method": "polysam", "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 2, "matrix": [[1, 2, 3, 4], [5, 6, 7, 8], [9, 10, 12, 13]]}]})");
  EXPECT_TRUE(std::holds_alternative<SpacePoseKeys>(scene.keys));
  EXPECT_EQ(dimension_of(scene), 3);
  EXPECT_EQ(method_id(scene.keys), "polySAM");
  ASSERT_EQ(space_keys(scene).poses.size(), 2u);
  EXPECT_EQ(space_keys(scene).poses[1].t, 2.0);
  EXPECT_EQ(space_keys(scene).poses[1].pose.L(1, 2), 7.0);
  EXPECT_EQ(space_keys(scene).poses[1].pose.L(2, 2), 12.0);
  EXPECT_EQ(space_keys(scene).poses[1].pose.b, Vector3d(4, 8, 13));
  ASSERT_EQ(scene.panels.size(), 1u);
  EXPECT_EQ(dimension_of(scene.panels[0]), 3);
  EXPECT_EQ(space_keys(scene.panels[0]).poses.size(), 2u);
}

// A tetrahedron pose maps the reference tetrahedron's points onto its own, in order.
TEST(SpacePoseScene, TetrahedraMapTheReferenceTetrahedron) {
  const Scene scene = parse_space(R"({"dimension": 3, "method": "SAM",
      "reference_tetrahedron": [[1, 1, 1], [3, 1, 1], [1, 2, 1], [1, 1, 5]],
      "poses": [{"t": 0, "tetrahedron": [[1, 1, 1], [3, 1, 1], [1, 2, 1], [1, 1, 5]]},
                {"t": 1, "tetrahedron": [[0, 0, 0], [0, 2, 0], [-1, 0, 0], [0, 0, 4]]}]})");
  ASSERT_EQ(space_keys(scene).poses.size(), 2u);
  EXPECT_LT((space_keys(scene).poses[0].pose.L - Eigen::Matrix3d::Identity()).norm() +
                space_keys(scene).poses[0].pose.b.norm(),
            1e-15);
  const Affine3& A = space_keys(scene).poses[1].pose;
  EXPECT_LT((apply(A, Vector3d(1, 1, 1)) - Vector3d(0, 0, 0)).norm(), 1e-14);
  EXPECT_LT((apply(A, Vector3d(3, 1, 1)) - Vector3d(0, 2, 0)).norm(), 1e-14);
  EXPECT_LT((apply(A, Vector3d(1, 2, 1)) - Vector3d(-1, 0, 0)).norm(), 1e-14);
  EXPECT_LT((apply(A, Vector3d(1, 1, 5)) - Vector3d(0, 0, 4)).norm(), 1e-14);
}

// "timing" reads as in 2D and reaches the scene's panel.
TEST(SpacePoseScene, TimingIsReadAsInThePlane) {
  const Scene scene = parse_space(R"({"dimension": 3, "method": "polySAM",
      "timing": {"ease": "ease-in", "arc_length": "q", "per": "span"}, "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[2, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]]}]})");
  ASSERT_EQ(scene.panels.size(), 1u);
  const Timing& timing = scene.panels[0].timing;
  EXPECT_EQ(timing.ease, *find_named_ease("ease-in"));
  EXPECT_EQ(timing.arc_length, TrackedPoint::end);
  EXPECT_EQ(timing.per, WarpSpan::span);
  EXPECT_EQ(timing.pointer, "/timing");
}

// "animation" is read as in a scene of poses of the plane (the refusals:
// tests/data/bad/space-animation-*).
TEST(SpacePoseScene, AnimationIsReadAsInThePlane) {
  const Scene scene = parse_space(R"({"dimension": 3, "method": "SAM",
      "animation": {"frames": 12, "loop": false, "trail": 3}, "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[2, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]]}]})");
  EXPECT_TRUE(scene.has_animation);
  EXPECT_EQ(scene.animation.frames, 12);
  EXPECT_FALSE(scene.animation.loop);
  EXPECT_EQ(scene.animation.trail, 3);
  EXPECT_EQ(scene.animation.what, Animation::What::motion);
  EXPECT_FALSE(parse_space(R"({"dimension": 3, "method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[2, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]]}]})")
                   .has_animation);
}

// "dimension": 2 is the plane's scene as before.
TEST(SpacePoseScene, DimensionTwoIsThePlane) {
  const Scene plane = parse_scene(R"({"dimension": 2, "method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 0], [0, 1, 0]]}]})",
                                  "s.json");
  EXPECT_EQ(dimension_of(plane), 2);
  EXPECT_EQ(plane_keys(plane).poses.size(), 2u);
}

// The method override of pita eval --method keeps to the SAM family in space.
TEST(SpacePoseScene, MethodOverrideKeepsToTheSamFamily) {
  const Scene scene = parse_space(R"({"dimension": 3, "method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}]})");
  EXPECT_EQ(pose_method_of(with_method(scene, PoseMethod::linear).panels[0]), PoseMethod::linear);
  try {
    (void)with_method(scene, PoseMethod::tsb);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/dimension");
  }
}

// "panels" of a 3D scene: a method of the SAM family by name, or an object
// with its own method, poses (matrices or tetrahedra), samples and layers;
// the scene's otherwise. Refusals: tests/data/bad/space-panel-*.
TEST(SpacePoseScene, PanelsOverrideTheMethodPosesAndLayers) {
  const Scene scene = parse_space(R"({"dimension": 3, "method": "SAM", "samples": 7, "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[1, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 0]]}],
      "panels": ["polySAM", {"method": "linear", "samples": 3, "layers": [{"type": "paths"}], "poses": [
      {"t": 0, "tetrahedron": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]},
      {"t": 2, "tetrahedron": [[0, 0, 5], [1, 0, 5], [0, 1, 5], [0, 0, 6]]}]}]})");
  ASSERT_EQ(scene.panels.size(), 2u);
  const SpacePoseKeys& first = std::get<SpacePoseKeys>(scene.panels[0].keys);
  EXPECT_EQ(first.method, PoseMethod::poly_sam);
  EXPECT_EQ(first.poses.size(), 2u);  // the scene's
  EXPECT_EQ(first.poses[1].pose.b.x(), 4.0);
  EXPECT_EQ(scene.panels[0].title, "polySAM");
  EXPECT_EQ(scene.panels[0].motion_pointer, "/panels/0");
  EXPECT_EQ(scene.panels[0].samples, 7);
  const SpacePoseKeys& second = std::get<SpacePoseKeys>(scene.panels[1].keys);
  EXPECT_EQ(second.method, PoseMethod::linear);
  ASSERT_EQ(second.poses.size(), 2u);
  EXPECT_EQ(second.poses[1].t, 2.0);
  EXPECT_EQ(second.poses[1].pose.b, Eigen::Vector3d(0.0, 0.0, 5.0));  // the tetrahedron's translation
  EXPECT_TRUE(second.poses[1].pose.L.isIdentity());
  EXPECT_EQ(scene.panels[1].motion_pointer, "/panels/1/poses");
  EXPECT_EQ(scene.panels[1].samples, 3);
  ASSERT_TRUE(figure_of<SpacePoseKeys>(scene.panels[1]).layers.has_value());
  EXPECT_TRUE(std::holds_alternative<PathsLayer>(figure_of<SpacePoseKeys>(scene.panels[1]).layers->at(0)));
}

}  // namespace
}  // namespace pita::scene
