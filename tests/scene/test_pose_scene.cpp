// Pose scenes (SAM paper; README "Pose scenes"): what the reader makes of
// poses given as matrices or triangles, shapes, panels, and what it refuses.
// The schema side of the same cases is in test_schema.cpp.
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

TEST(PoseScene, NoSamIsRefusedWithTheIssuesMessage) {
  const std::string message = error_of(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[-2, 0, 1], [0, -0.5, 1]]}]})");
  EXPECT_EQ(message.rfind("s.json: /poses: no SAM exists between these poses: ", 0), 0u) << message;
  EXPECT_NE(message.find("G3"), std::string::npos) << message;
  EXPECT_NE(message.find("middle pose"), std::string::npos) << message;
  // Through a middle pose, the polySAM and the bi-arc exist.
  const std::string three = R"([{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 0.5, "matrix": [[0, -0.8, 4.5], [1.25, 0, 3.5]]}, {"t": 1, "matrix": [[-1.6, 0, 9.5], [0, -0.6, 1]]}])";
  EXPECT_EQ(error_of(R"({"method": "polySAM", "poses": )" + three + "}"), "(no error)");
  EXPECT_EQ(error_of(R"({"method": "biarc-SAM", "poses": )" + three + "}"), "(no error)");
  // A panel whose SAM does not exist is named.
  const std::string panel = error_of(R"({"method": "polySAM", "poses": )" + three +
                                     R"(, "panels": [{"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
                                        {"t": 1, "matrix": [[-1.6, 0, 9.5], [0, -0.6, 1]]}]}]})");
  EXPECT_EQ(panel.rfind("s.json: /panels/0/poses: no SAM exists between these poses", 0), 0u) << panel;
}

TEST(PoseScene, BadPosesNameTheValue) {
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[1, 2, 0], [0.5, 1, 0]]}]})"),
            "s.json: /poses/1/matrix: the linear part [[a, b], [c, d]] has determinant 0 (its singular "
            "values differ by more than 1e16): the pose is singular, it flattens the plane onto a "
            "line or a point");
  // A strong stretch is not singular.
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[1e7, 0, 0], [0, 1e-7, 0]]}]})"),
            "(no error)");
  // Knots closer than the four-point subdivision can split.
  const std::string close = error_of(R"({"method": "four-point-SAM", "subdivisions": 1, "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0.5, -1, 2], [1.2, 0.7, -1]]},
      {"t": 1.0000000000000002, "matrix": [[0.4, -1, 2], [1.2, 0.7, -1]]}, {"t": 3, "matrix": [[1, 0, 5], [0, 1, 0]]}]})");
  EXPECT_EQ(close.rfind("s.json: /poses: four-point-SAM: two knots are too close for 1 subdivisions", 0), 0u)
      << close;
  // A pose and a mirrored one: no SAM (C o B^-1 reverses orientation).
  const std::string mirrored = error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, 1, 0], [1, 0, 0]]}]})");
  EXPECT_EQ(mirrored.rfind("s.json: /poses: no SAM exists between these poses: ", 0), 0u) << mirrored;
  EXPECT_NE(mirrored.find("one is mirrored and the other is not"), std::string::npos) << mirrored;
  EXPECT_NE(mirrored.find("determinant -1 <= 0"), std::string::npos) << mirrored;
  EXPECT_NE(mirrored.find("no middle pose can help"), std::string::npos) << mirrored;
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "triangle": [[0, 0], [1, 1], [2, 2]]}]})"),
            "s.json: /poses/1/triangle: the triangle is degenerate (its points are collinear)");
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[1, 0, 1e300], [0, 1, 0]]}]})"),
            "s.json: /poses/1/matrix/0/2: must be within +-1e+100 (got 1e+300)");
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}]})"),
            "s.json: /poses: method SAM takes exactly 2 poses (got 1)");
  EXPECT_EQ(error_of(R"({"method": "SAMM", "poses": []})"),
            "s.json: /method: unknown pose method \"SAMM\"; did you mean \"SAM\"?");
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]],
      "triangle": [[0, 0], [1, 0], [0, 1]]}, {"t": 1, "matrix": [[1, 0, 0], [0, 1, 0]]}]})"),
            "s.json: /poses/0/triangle: give either \"matrix\" or \"triangle\", not both");
  EXPECT_EQ(error_of(R"({"method": "SAM", "layers": [{"type": "shapes"}]})"),
            "s.json: /poses: missing required field (an array of poses {\"t\": ..., \"matrix\": [[a, b, "
            "tx], [c, d, ty]]} or {\"t\": ..., \"triangle\": [[x, y], [x, y], [x, y]]})");
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[1, 0, 0], [0, 1, 0]]}], "layers": [{"type": "keyframes"}]})"),
            "s.json: /layers/0/type: layer type \"keyframes\" draws arrows (keyframe scenes); a pose "
            "scene's layers: shapes, poses, velocities, paths, existence, label, patch");
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
