// Reading pose scenes (src/scene/pose_reader.cpp; SAM paper, docs/reference/pose-scenes.md "Pose
// scenes"): poses given as matrices or triangles, the reference triangle,
// shapes and builtin outlines, pose methods; what it refuses is in
// tests/data/bad/ (poses-*), a few refusals are asserted whole here. The
// schema side of the same cases is in test_schema.cpp.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/limits.hpp"
#include "scene/pose_reader.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using detail::Json;
using detail::JsonReader;
using test::error_of;

using test::kReader;
const std::array<Point, 3> kUnitTriangle = {Point{0.0, 0.0}, Point{1.0, 0.0}, Point{0.0, 1.0}};

using test::failure;

Eigen::Vector2d image(const Affine2& A, double x, double y) { return apply(A, Eigen::Vector2d(x, y)); }

// One reader over the dimension: the frame of a simplex maps the unit
// simplex onto it, and a flat simplex is degenerate, in the plane and in space.
TEST(PoseReaderOverTheDimension, FrameOfMapsTheUnitSimplexOntoThePoints) {
  const std::array<Point, 3> triangle = {Point{1.0, 2.0}, Point{4.0, 2.0}, Point{1.0, 7.0}};
  const Affine2 plane = detail::frame_of<Affine2>(triangle);
  EXPECT_EQ(image(plane, 0.0, 0.0), Eigen::Vector2d(1.0, 2.0));
  EXPECT_EQ(image(plane, 1.0, 0.0), Eigen::Vector2d(4.0, 2.0));
  EXPECT_EQ(image(plane, 0.0, 1.0), Eigen::Vector2d(1.0, 7.0));
  const std::array<Eigen::Vector3d, 4> tetrahedron = {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(2, 2, 3),
                                                      Eigen::Vector3d(1, 4, 3), Eigen::Vector3d(1, 2, 6)};
  const Affine3 space = detail::frame_of<Affine3>(tetrahedron);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(apply(space, Eigen::Vector3d::Unit(i)), tetrahedron[static_cast<std::size_t>(i) + 1]) << i;
  }
  EXPECT_EQ(apply(space, Eigen::Vector3d::Zero()), tetrahedron[0]);
}

TEST(PoseReaderOverTheDimension, FlatSimplicesAreDegenerate) {
  EXPECT_FALSE(detail::degenerate<Affine2>(kUnitTriangle));
  EXPECT_TRUE(detail::degenerate<Affine2>({Point{0.0, 0.0}, Point{1.0, 1.0}, Point{3.0, 3.0}}));
  EXPECT_FALSE(detail::degenerate<Affine3>(
      {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}));
  EXPECT_TRUE(detail::degenerate<Affine3>(
      {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0)}));
}

TEST(PoseReaderOverTheDimension, MatricesAndReferencesSayTheirDimension) {
  const Affine3 A =
      detail::read_matrix<Affine3>(kReader, Json::parse("[[1, 2, 3, 4], [0, 1, 0, 5], [0, 0, 2, 6]]"), "/m");
  EXPECT_EQ(A.L(0, 2), 3.0);
  EXPECT_EQ(A.b, Eigen::Vector3d(4, 5, 6));
  EXPECT_TRUE(failure([] { detail::read_matrix<Affine2>(kReader, Json::parse("[[1, 0], [0, 1]]"), "/m"); })
                  .starts_with("/m: must be a 2x3 matrix [[a, b, tx], [c, d, ty]] (x -> [[a, b], [c, d]] x + "
                               "[tx, ty]; got array "));
  EXPECT_TRUE(failure([] { detail::read_matrix<Affine3>(kReader, Json::parse("[[1, 0, 0], [0, 1, 0]]"), "/m"); })
                  .starts_with("/m: a 2x3 matrix is a pose of the plane; the poses of a 3D scene (\"dimension\": "
                               "3) are 3x4 matrices [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]] (got array "));
  EXPECT_EQ(failure([] {
              detail::read_reference<Affine3>(kReader, Json::parse("[[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]"),
                                              "/reference_tetrahedron");
            }),
            "/reference_tetrahedron: the reference tetrahedron is degenerate (its points are coplanar)");
}

TEST(PoseScene, MatricesAreRowsOfTheAffinity) {
  const Scene scene = parse_scene(R"({"method": "sam", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 2, "matrix": [[1, 2, 3], [-4, 5, 6]]}]})",
                                  "s.json");
  EXPECT_TRUE(std::holds_alternative<PlanePoseKeys>(scene.keys));
  EXPECT_EQ(method_id(scene.keys), "SAM");
  ASSERT_EQ(plane_keys(scene).poses.size(), 2u);
  EXPECT_EQ(plane_keys(scene).poses[1].t, 2.0);
  // [[a, b, tx], [c, d, ty]]: x -> [[a, b], [c, d]] x + [tx, ty].
  EXPECT_EQ(image(plane_keys(scene).poses[1].pose, 1.0, 0.0), Eigen::Vector2d(4.0, 2.0));
  EXPECT_EQ(image(plane_keys(scene).poses[1].pose, 0.0, 1.0), Eigen::Vector2d(5.0, 11.0));
  // Defaults: the reference triangle as the shape; shapes and poses drawn.
  ASSERT_EQ(figure_of<PlanePoseKeys>(scene).shapes.size(), 1u);
  EXPECT_EQ(figure_of<PlanePoseKeys>(scene).shapes[0].points.size(), 3u);
  ASSERT_EQ(figure_of<PlanePoseKeys>(scene).layers.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<ShapesLayer>(figure_of<PlanePoseKeys>(scene).layers[0]));
  EXPECT_TRUE(std::holds_alternative<PosesLayer>(figure_of<PlanePoseKeys>(scene).layers[1]));
  ASSERT_EQ(scene.panels.size(), 1u);
  EXPECT_EQ(plane_keys(scene.panels[0]).poses.size(), 2u);
}

TEST(PoseScene, TrianglesMapTheReferenceTriangle) {
  const Scene scene = parse_scene(R"({"method": "SAM", "reference_triangle": [[1, 1], [3, 1], [1, 2]],
      "poses": [{"t": 0, "triangle": [[1, 1], [3, 1], [1, 2]]},
                {"t": 1, "triangle": [[5, 5], [5, 9], [3.5, 5]]}]})",
                                  "s.json");
  const Affine2& first = plane_keys(scene).poses[0].pose;
  EXPECT_LT((first.L - Eigen::Matrix2d::Identity()).norm() + first.b.norm(), 1e-15);
  const Affine2& second = plane_keys(scene).poses[1].pose;
  EXPECT_LT((image(second, 1, 1) - Eigen::Vector2d(5, 5)).norm(), 1e-14);
  EXPECT_LT((image(second, 3, 1) - Eigen::Vector2d(5, 9)).norm(), 1e-14);
  EXPECT_LT((image(second, 1, 2) - Eigen::Vector2d(3.5, 5)).norm(), 1e-14);
  // "triangle": "reference" is the reference triangle's outline.
  ASSERT_EQ(figure_of<PlanePoseKeys>(scene).shapes[0].points.size(), 3u);
  EXPECT_EQ(figure_of<PlanePoseKeys>(scene).shapes[0].points[1], Point(3, 1));
}

// Two mirrored poses: C o B^-1 preserves orientation, so the SAM exists and
// every frame is mirrored.
TEST(PoseScene, MirroredPosesHaveASam) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "triangle": [[0, 0], [0, 1], [1, 0]]}, {"t": 1, "triangle": [[3, 0], [3, 2], [5, 0]]}]})",
                                  "s.json");
  EXPECT_LT(plane_keys(scene).poses[0].pose.L.determinant(), 0.0);
  const PoseMotion motion(pose_method_of(scene), plane_keys(scene).poses);
  EXPECT_LT(motion.at(0.5).L.determinant(), 0.0);
}

TEST(PoseScene, BuiltinOutlines) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}],
      "shapes": [{"outline": "F"}, {"outline": "picture", "color": "red"}, {"outline": "square"}]})",
                                  "s.json");
  ASSERT_EQ(figure_of<PlanePoseKeys>(scene).shapes.size(), 1u + 7u + 1u);  // the picture has seven parts, all red
  EXPECT_EQ(figure_of<PlanePoseKeys>(scene).shapes[0].points.size(), 10u);
  EXPECT_FALSE(figure_of<PlanePoseKeys>(scene).shapes[0].color.has_value());
  for (std::size_t i = 1; i <= 7; ++i) {
    ASSERT_TRUE(figure_of<PlanePoseKeys>(scene).shapes[i].color.has_value()) << i;
    EXPECT_EQ(*figure_of<PlanePoseKeys>(scene).shapes[i].color, *figure_of<PlanePoseKeys>(scene).shapes[1].color) << i;
    for (const Point p : figure_of<PlanePoseKeys>(scene).shapes[i].points) {
      EXPECT_TRUE(p.real() >= 0.0 && p.real() <= 1.0 && p.imag() >= 0.0 && p.imag() <= 0.75) << i;
    }
  }
  EXPECT_FALSE(figure_of<PlanePoseKeys>(scene).shapes[2].closed);  // the ground line
  EXPECT_EQ(figure_of<PlanePoseKeys>(scene).shapes[8].points.size(), 4u);
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

TEST(PoseReader, PoseCountReasonSaysExactlyOrARange) {
  EXPECT_EQ(detail::pose_count_reason(PoseMethod::sam, 3), "method SAM takes exactly 2 poses (got 3)");
  EXPECT_EQ(detail::pose_count_reason(PoseMethod::poly_sam, 1), "method polySAM takes 2 to 1000 poses (got 1)");
  EXPECT_EQ(detail::pose_count_reason(PoseMethod::bezier_sam, 5), "method bezier-SAM takes 3 to 4 poses (got 5)");
}

TEST(PoseReader, PoseMethodsByNameAndArrowMethodsRefused) {
  EXPECT_EQ(detail::read_pose_method(kReader, Json("polySAM"), "/method"), PoseMethod::poly_sam);
  EXPECT_EQ(detail::read_pose_method(kReader, Json("linear"), "/method"), PoseMethod::linear);
  // The PITAs P4, P5, P6 and P9 are also pose methods (docs/paper-notes.md N73); the others are refused.
  EXPECT_EQ(detail::read_pose_method(kReader, Json("P6"), "/method"), PoseMethod::p6);
  EXPECT_EQ(detail::read_pose_method(kReader, Json("ne-lp"), "/method"), PoseMethod::p9);
  EXPECT_EQ(failure([] { detail::read_pose_method(kReader, Json("P8"), "/method"); }),
            "/method: method P8 interpolates arrows, and this is a pose scene: give it "
            "\"keyframes\" instead, or a pose method such as SAM");
  const std::string not_a_name = failure([] { detail::read_pose_method(kReader, Json(3), "/method"); });
  EXPECT_EQ(not_a_name.rfind("/method: must be a pose method: \"SAM\", ", 0), 0u) << not_a_name;
  EXPECT_NE(not_a_name.find(" (got 3)"), std::string::npos) << not_a_name;
}

// A triangle pose is the affinity that maps the reference triangle onto it:
// with the unit reference triangle, its columns are the edges from the first point.
TEST(PoseReader, TrianglePoseMapsTheReferenceOntoTheTriangle) {
  const std::vector<TimedPose> poses =
      detail::read_poses<Affine2>(kReader, Json::parse(R"([{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
                               {"t": 1.5, "triangle": [[2, 1], [4, 1], [2, 4]]}])"),
                                  "/poses", kUnitTriangle, PoseMethod::sam);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[1].t, 1.5);
  Eigen::Matrix2d L;
  L << 2.0, 0.0, 0.0, 3.0;
  EXPECT_LT((poses[1].pose.L - L).norm(), 1e-15);
  EXPECT_LT((poses[1].pose.b - Eigen::Vector2d(2.0, 1.0)).norm(), 1e-15);
}

TEST(PoseReader, RefusalsNameTheValueAndTheReason) {
  EXPECT_EQ(failure([] {
              detail::read_poses<Affine2>(kReader, Json::parse(R"([{"t": 1, "matrix": [[1, 0, 0], [0, 1, 0]]},
                                                          {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}])"),
                                          "/poses", kUnitTriangle, PoseMethod::sam);
            }),
            "/poses/1/t: times must increase strictly: 1 follows 1");
  EXPECT_EQ(failure([] {
              detail::read_poses<Affine2>(kReader, Json::parse(R"([{"t": 0, "matrix": [[1, 2, 0], [2, 4, 0]]},
                                                          {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}])"),
                                          "/poses", kUnitTriangle, PoseMethod::sam);
            }),
            "/poses/0/matrix: the linear part [[a, b], [c, d]] has determinant 0 (its singular values "
            "differ by more than 1e16): the pose is singular, it flattens the plane onto a line or a point");
  EXPECT_EQ(failure([] {
              detail::read_poses<Affine2>(kReader, Json::parse(R"([{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]],
                                                           "triangle": [[0, 0], [1, 0], [0, 1]]},
                                                          {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}])"),
                                          "/poses", kUnitTriangle, PoseMethod::sam);
            }),
            "/poses/0/triangle: give either \"matrix\" or \"triangle\", not both");
  EXPECT_EQ(failure([] {
              detail::read_reference<Affine2>(kReader, Json::parse("[[0, 0], [1, 1], [3, 3]]"), "/reference_triangle");
            }),
            "/reference_triangle: the reference triangle is degenerate (its points are collinear)");
}

TEST(PoseReader, BuiltinOutlinesLieInTheUnitBox) {
  const auto inside = [](const std::vector<ShapeOutline>& parts) {
    for (const ShapeOutline& part : parts) {
      for (const Point p : part.points) {
        if (p.real() < 0.0 || p.real() > 1.0 || p.imag() < 0.0 || p.imag() > 1.0) return false;
      }
    }
    return true;
  };
  const std::vector<ShapeOutline> square = detail::builtin_outline("square");
  ASSERT_EQ(square.size(), 1u);
  EXPECT_EQ(square[0].points, (std::vector<Point>{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}));
  EXPECT_TRUE(square[0].closed);
  EXPECT_EQ(detail::builtin_outline("F")[0].points.size(), 10u);
  EXPECT_EQ(detail::builtin_outline("house")[0].points.size(), 5u);
  const std::vector<ShapeOutline> picture = detail::builtin_outline("picture");
  EXPECT_EQ(picture.size(), 7u);
  for (const char* name : {"F", "house", "square", "picture"})
    EXPECT_TRUE(inside(detail::builtin_outline(name))) << name;
}

TEST(PoseReader, ShapesKeepTheirKindColourAndOrder) {
  const std::vector<ShapeOutline> shapes =
      detail::read_shapes(kReader, Json::parse(R"([{"polyline": [[0, 0], [2, 1]], "color": "#ff0000"},
                               {"triangle": "reference"}, {"outline": "picture"}, {"polygon": [[0, 0], [1, 0], [0, 2]]}])"),
                          "/shapes", kUnitTriangle);
  ASSERT_EQ(shapes.size(), 1u + 1u + 7u + 1u);  // the picture's parts follow it
  EXPECT_FALSE(shapes[0].closed);
  EXPECT_EQ(shapes[0].points, (std::vector<Point>{{0.0, 0.0}, {2.0, 1.0}}));
  ASSERT_TRUE(shapes[0].color.has_value());
  EXPECT_EQ(shapes[0].color->r, 1.0);
  EXPECT_EQ(shapes[1].points, (std::vector<Point>(kUnitTriangle.begin(), kUnitTriangle.end())));
  EXPECT_TRUE(shapes[9].closed);
  EXPECT_EQ(shapes[9].points.back(), (Point{0.0, 2.0}));
  EXPECT_EQ(
      failure([] { detail::read_shapes(kReader, Json::parse(R"([{"triangle": "mine"}])"), "/shapes", kUnitTriangle); }),
      "/shapes/0/triangle: must be \"reference\" (the reference triangle; got string \"mine\")");
}

// An image shape {"image", "box"} (PITA Sec. 7.1): its points are the box's
// corners counter-clockwise from (x0, y0); the file is found beside the
// scene file (here the repository's scenes/images/picture.png, 160 x 120).
TEST(PoseReader, ImageShapesAreTheirBoxAndFile) {
  const JsonReader reader((std::filesystem::path(PITA_SOURCE_DIR) / "scenes" / "s.json").string());
  const std::vector<ShapeOutline> shapes = detail::read_shapes(
      reader, Json::parse(R"([{"image": "images/picture.png", "box": [[1, 2], [5, 4]], "color": "red"},
                               {"outline": "square"}])"),
      "/shapes", kUnitTriangle);
  ASSERT_EQ(shapes.size(), 2u);
  ASSERT_TRUE(shapes[0].image.has_value());
  EXPECT_EQ(shapes[0].image->given, "images/picture.png");
  EXPECT_EQ(shapes[0].image->width, 160);
  EXPECT_EQ(shapes[0].image->height, 120);
  EXPECT_TRUE(std::filesystem::equivalent(shapes[0].image->path,
                                          std::filesystem::path(PITA_SOURCE_DIR) / "scenes/images/picture.png"));
  EXPECT_TRUE(shapes[0].closed);
  EXPECT_EQ(shapes[0].points, (std::vector<Point>{{1.0, 2.0}, {5.0, 2.0}, {5.0, 4.0}, {1.0, 4.0}}));
  ASSERT_TRUE(shapes[0].color.has_value());
  EXPECT_FALSE(shapes[1].image.has_value());

  const auto refusal = [&reader](const std::string& shape) {
    return failure([&] { detail::read_shapes(reader, Json::parse("[" + shape + "]"), "/shapes", kUnitTriangle); },
                   reader.file());
  };
  EXPECT_EQ(refusal(R"({"image": "images/picture.png"})"),
            "/shapes/0/box: missing required field (where the image goes: [[x0, y0], [x1, y1]], its lower-left and "
            "upper-right corners)");
  EXPECT_EQ(refusal(R"({"image": "images/picture.png", "box": [[1, 0], [0, 1]]})"),
            "/shapes/0/box: the box must have x0 < x1 and y0 < y1 (got array [[1,0],[0,1]])");
  EXPECT_EQ(refusal(R"({"image": "images/picture.png", "box": [[0, 1], [1, 1]]})"),
            "/shapes/0/box: the box must have x0 < x1 and y0 < y1 (got array [[0,1],[1,1]])");
  EXPECT_EQ(refusal(R"({"image": "images/picture.png", "box": [[0, 0], [1, 1], [2, 2]]})"),
            "/shapes/0/box: must be [[x0, y0], [x1, y1]] (got array [[0,0],[1,1],[2,2]])");
  EXPECT_EQ(refusal(R"({"box": [[0, 0], [1, 1]]})"), "/shapes/0/box: \"box\" places an \"image\"; this shape has none");
  EXPECT_EQ(refusal(R"({"image": "images/missing.png", "box": [[0, 0], [1, 1]]})"),
            "/shapes/0/image: image \"images/missing.png\" does not exist (image paths are relative to the scene's "
            "folder)");
  EXPECT_EQ(refusal(R"({"outline": "F", "image": "images/picture.png", "box": [[0, 0], [1, 1]]})"),
            "/shapes/0/image: a shape is one of \"polygon\", \"polyline\", \"triangle\", \"outline\" or "
            "\"image\"; give only one");
  std::string seventeen;
  for (int i = 0; i <= kMaxImages; ++i) {
    seventeen += std::string(i > 0 ? ", " : "") + R"({"image": "images/picture.png", "box": [[0, 0], [1, 1]]})";
  }
  EXPECT_EQ(refusal(seventeen), "/shapes/16/image: at most 16 images in a scene");
}

// Pose scenes take image shapes too, found beside the scene file.
TEST(PoseScene, ImageShapes) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -2, 3], [2, 0, 1]]}], "shapes": [{"image": "images/picture.png", "box": [[0, 0], [1, 0.75]]}]})",
                                  (std::filesystem::path(PITA_SOURCE_DIR) / "scenes" / "s.json").string());
  ASSERT_EQ(figure_of<PlanePoseKeys>(scene).shapes.size(), 1u);
  ASSERT_TRUE(figure_of<PlanePoseKeys>(scene).shapes[0].image.has_value());
  EXPECT_EQ(figure_of<PlanePoseKeys>(scene).shapes[0].image->width, 160);
  EXPECT_EQ(error_of(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -2, 3], [2, 0, 1]]}], "shapes": [{"image": "/etc/passwd", "box": [[0, 0], [1, 1]]}]})"),
            "s.json: /shapes/0/image: \"/etc/passwd\" is an absolute path; images are found relative to the scene's "
            "folder (pass --allow-absolute-paths to allow absolute ones)");
}

}  // namespace
}  // namespace pita::scene
