// Pose scenes (SAM paper; README "Pose scenes"): what the reader makes of
// poses given as matrices or triangles, shapes, panels; what it refuses is in
// tests/data/bad/ (poses-*). The schema side of the same cases is in
// test_schema.cpp.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::error_of;

Eigen::Vector2d image(const Affine2& A, double x, double y) { return apply(A, Eigen::Vector2d(x, y)); }

TEST(PoseScene, MatricesAreRowsOfTheAffinity) {
  const Scene scene = parse_scene(R"({"method": "sam", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 2, "matrix": [[1, 2, 3], [-4, 5, 6]]}]})",
                                  "s.json");
  EXPECT_EQ(scene.kind, SceneKind::poses);
  EXPECT_EQ(scene.method_name, "SAM");
  ASSERT_EQ(scene.poses.size(), 2u);
  EXPECT_EQ(scene.poses[1].t, 2.0);
  // [[a, b, tx], [c, d, ty]]: x -> [[a, b], [c, d]] x + [tx, ty].
  EXPECT_EQ(image(scene.poses[1].pose, 1.0, 0.0), Eigen::Vector2d(4.0, 2.0));
  EXPECT_EQ(image(scene.poses[1].pose, 0.0, 1.0), Eigen::Vector2d(5.0, 11.0));
  // Defaults: the reference triangle as the shape; shapes and poses drawn.
  ASSERT_EQ(scene.shapes.size(), 1u);
  EXPECT_EQ(scene.shapes[0].points.size(), 3u);
  ASSERT_EQ(scene.pose_layers.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<ShapesLayer>(scene.pose_layers[0]));
  EXPECT_TRUE(std::holds_alternative<PosesLayer>(scene.pose_layers[1]));
  ASSERT_EQ(scene.panels.size(), 1u);
  EXPECT_EQ(scene.panels[0].poses.size(), 2u);
}

TEST(PoseScene, TrianglesMapTheReferenceTriangle) {
  const Scene scene = parse_scene(R"({"method": "SAM", "reference_triangle": [[1, 1], [3, 1], [1, 2]],
      "poses": [{"t": 0, "triangle": [[1, 1], [3, 1], [1, 2]]},
                {"t": 1, "triangle": [[5, 5], [5, 9], [3.5, 5]]}]})",
                                  "s.json");
  const Affine2& first = scene.poses[0].pose;
  EXPECT_LT((first.L - Eigen::Matrix2d::Identity()).norm() + first.b.norm(), 1e-15);
  const Affine2& second = scene.poses[1].pose;
  EXPECT_LT((image(second, 1, 1) - Eigen::Vector2d(5, 5)).norm(), 1e-14);
  EXPECT_LT((image(second, 3, 1) - Eigen::Vector2d(5, 9)).norm(), 1e-14);
  EXPECT_LT((image(second, 1, 2) - Eigen::Vector2d(3.5, 5)).norm(), 1e-14);
  // "triangle": "reference" is the reference triangle's outline.
  ASSERT_EQ(scene.shapes[0].points.size(), 3u);
  EXPECT_EQ(scene.shapes[0].points[1], Point(3, 1));
}

// Two mirrored poses: C o B^-1 preserves orientation, so the SAM exists and
// every frame is mirrored.
TEST(PoseScene, MirroredPosesHaveASam) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "triangle": [[0, 0], [0, 1], [1, 0]]}, {"t": 1, "triangle": [[3, 0], [3, 2], [5, 0]]}]})",
                                  "s.json");
  EXPECT_LT(scene.poses[0].pose.L.determinant(), 0.0);
  const PoseMotion motion(scene.pose_method, scene.poses);
  EXPECT_LT(motion.at(0.5).L.determinant(), 0.0);
}

TEST(PoseScene, BuiltinOutlines) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}],
      "shapes": [{"outline": "F"}, {"outline": "picture", "color": "red"}, {"outline": "square"}]})",
                                  "s.json");
  ASSERT_EQ(scene.shapes.size(), 1u + 7u + 1u);  // the picture has seven parts, all red
  EXPECT_EQ(scene.shapes[0].points.size(), 10u);
  EXPECT_FALSE(scene.shapes[0].color.has_value());
  for (std::size_t i = 1; i <= 7; ++i) {
    ASSERT_TRUE(scene.shapes[i].color.has_value()) << i;
    EXPECT_EQ(*scene.shapes[i].color, *scene.shapes[1].color) << i;
    for (const Point p : scene.shapes[i].points) {
      EXPECT_TRUE(p.real() >= 0.0 && p.real() <= 1.0 && p.imag() >= 0.0 && p.imag() <= 0.75) << i;
    }
  }
  EXPECT_FALSE(scene.shapes[2].closed);  // the ground line
  EXPECT_EQ(scene.shapes[8].points.size(), 4u);
}

TEST(PoseScene, PanelsInheritAndOverride) {
  const Scene scene = parse_scene(R"({"method": "polySAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0, -1, 2], [1, 0, 2]]},
      {"t": 2, "matrix": [[-1, 0, 4], [0, -1, 0]]}],
      "panels": ["linear", {"method": "biarc-SAM", "samples": 5},
                 {"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
                                             {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}]}]})",
                                  "s.json");
  ASSERT_EQ(scene.panels.size(), 3u);
  EXPECT_EQ(scene.panels[0].pose_method, PoseMethod::linear);
  EXPECT_EQ(scene.panels[0].poses.size(), 3u);
  EXPECT_EQ(scene.panels[1].pose_method, PoseMethod::biarc_sam);
  EXPECT_EQ(scene.panels[1].samples, 5);
  EXPECT_EQ(scene.panels[2].poses.size(), 2u);
  EXPECT_EQ(scene.panels[2].title, "SAM");
}

// The refusals (no SAM, singular or degenerate poses, knots too close, ...)
// are the poses-* files of tests/data/bad/ (test_bad_scenes.cpp). Their good
// neighbours are here.

// Poses without a SAM between the first and the last: through a middle pose,
// the polySAM and the bi-arc exist.
TEST(PoseScene, MiddlePoseGivesPolySamAndBiarc) {
  const std::string three = R"([{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 0.5, "matrix": [[0, -0.8, 4.5], [1.25, 0, 3.5]]}, {"t": 1, "matrix": [[-1.6, 0, 9.5], [0, -0.6, 1]]}])";
  EXPECT_EQ(error_of(R"({"method": "polySAM", "poses": )" + three + "}"), "(no error)");
  EXPECT_EQ(error_of(R"({"method": "biarc-SAM", "poses": )" + three + "}"), "(no error)");
}

// A strong stretch is not singular.
TEST(PoseScene, StrongStretchIsNotSingular) {
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[1e7, 0, 0], [0, 1e-7, 0]]}]})"),
            "(no error)");
}

TEST(PoseScene, MethodOverride) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0, -1, 2], [1, 0, 2]]}]})",
                                  "s.json");
  EXPECT_EQ(with_pose_method(scene, PoseMethod::linear).method_name, "linear");
  EXPECT_THROW(with_pose_method(scene, PoseMethod::biarc_sam), SceneError);  // 3 poses
  EXPECT_THROW(with_method(scene, Method::P6), SceneError);
}

}  // namespace
}  // namespace pita::scene
