// The geometry of pose scenes (render/pose_drawing.hpp), in the plane and in
// space: shapes carried by the motion, velocity arrows and vertex paths, each
// checked against an independent computation (Eigen's matrix power and log);
// in space the painter's order and the faces of a drawn solid. The charts drawn
// without a motion: tests/render/layers/.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <variant>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "../core/pose_test_support.hpp"
#include "render/pose_drawing.hpp"
#include "support/keys.hpp"
#include "support/matrix_functions.hpp"

namespace pita::render {
namespace {

using pita::test::affinity;

Eigen::Matrix3d homogeneous(const Affine2& A) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Identity();
  H.topLeftCorner<2, 2>() = A.L;
  H.topRightCorner<2, 1>() = A.b;
  return H;
}

Point through(const Eigen::Matrix3d& H, Point p) {
  const Eigen::Vector3d x = H * Eigen::Vector3d(p.real(), p.imag(), 1.0);
  return {x.x(), x.y()};
}

// A SAM scene of two poses of the reference triangle, with `layers`.
scene::Scene sam_scene(std::vector<scene::PoseLayer> layers, PoseMethod method = PoseMethod::sam) {
  scene::Scene s;
  s.path = "test.json";
  scene::PlanePoseKeys keys;
  keys.method = method;
  keys.poses = {{0.0, affinity(1.0, 0.2, 0.0, 0.0, 1.0, 0.0)}, {2.0, affinity(-0.5, -1.4, 5.0, 1.1, 0.3, 2.0)}};
  s.keys = keys;
  scene::PoseFigure<Affine2> figure;
  figure.shapes = {scene::ShapeOutline{{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}}, true, std::nullopt, std::nullopt}};
  figure.layers = std::move(layers);
  scene::Panel panel;
  panel.keys = keys;
  panel.figure = scene::PosePanelFigure<Affine2>{std::nullopt, figure.shapes};
  s.figure = std::move(figure);
  panel.samples = 5;
  s.panels = {panel};
  return s;
}

TEST(PoseDrawing, ShapesFollowTheSam) {
  const scene::Scene scene = sam_scene({scene::ShapesLayer{}});
  const Drawing drawing = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 5u);
  // Independently: A = C B^-1 by Eigen, A^u by Eigen's pow, at u = i/4.
  const Eigen::Matrix3d B = homogeneous(plane_keys(scene).poses[0].pose),
                        C = homogeneous(plane_keys(scene).poses[1].pose);
  const Eigen::Matrix3d A = C * B.inverse();
  for (int i = 0; i < 5; ++i) {
    const auto& outline = std::get<Polyline>(drawing.items[static_cast<std::size_t>(i)].shape);
    EXPECT_TRUE(outline.closed);
    const Eigen::Matrix3d pose = oracle::pow(A, i / 4.0) * B;
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_LT(std::abs(outline.points[k] -
                         through(pose, scene::figure_of<scene::PlanePoseKeys>(scene).shapes[0].points[k])),
                1e-11)
          << "frame " << i << ", vertex " << k;
    }
  }
}

// Sec. 2.3 (6): the velocity of a SAM is the constant field x -> log(A) x
// (per unit of normalised time); the arrows are that field, scaled.
TEST(PoseDrawing, SamVelocitiesAreTheLogField) {
  scene::VelocitiesLayer layer;
  layer.scale = 0.5;
  const scene::Scene scene = sam_scene({layer});
  const Drawing drawing = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 15u);  // 5 frames x 3 vertices
  const Eigen::Matrix3d A =
      homogeneous(plane_keys(scene).poses[1].pose) * homogeneous(plane_keys(scene).poses[0].pose).inverse();
  const Eigen::Matrix3d field = oracle::log(A);
  for (const Item& item : drawing.items) {
    const auto& arrow = std::get<ArrowShape>(item.shape);
    const Eigen::Vector3d v = field * Eigen::Vector3d(arrow.from.real(), arrow.from.imag(), 1.0);
    const Point expected = arrow.from + 0.5 * Point(v.x(), v.y());
    EXPECT_LT(std::abs(arrow.to - expected), 1e-11 * (1.0 + std::abs(expected))) << item.index;
  }
}

TEST(PoseDrawing, LinearMotionMovesVerticesOnStraightLines) {
  const scene::Scene scene = sam_scene({scene::PathsLayer{}}, PoseMethod::linear);
  const Drawing drawing = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 3u);
  for (const Item& item : drawing.items) {
    const auto& path = std::get<Polyline>(item.shape);
    const Point from = path.points.front(), to = path.points.back();
    for (const Point p : path.points) {
      const double cross = std::imag(std::conj(to - from) * (p - from));
      EXPECT_LT(std::abs(cross), 1e-12 * std::norm(to - from));
    }
  }
}

TEST(PoseDrawing, PosesLayerDrawsEachControlPose) {
  const scene::Scene scene = sam_scene({scene::PosesLayer{}});
  const Drawing drawing = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 2u);
  const auto& last = std::get<FilledPath>(drawing.items[1].shape);
  EXPECT_LT(std::abs(last.contours[0][1] - through(homogeneous(plane_keys(scene).poses[1].pose), {1.0, 0.0})), 1e-15);
}

// Fig. 11: a regular patch of 3 x 2 shapes from the first three poses; its
// corners are the poses (and the computed fourth corner), and a patch asks
// for enough poses.
TEST(PoseDrawing, PatchCornersAreThePoses) {
  scene::Scene scene = sam_scene({});
  plane_keys(scene.panels[0]).poses.push_back({3.0, affinity(1.1, 0.2, 0.5, 0.1, 0.9, -3.0)});
  scene::PatchLayer layer;
  layer.columns = 3;
  layer.rows = 2;
  layer.regular = true;
  scene::figure_of<scene::PlanePoseKeys>(scene).layers = {layer};
  const Drawing drawing = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 6u);
  const auto corner = [&](std::size_t item) {
    return std::get<Polyline>(drawing.items[item].shape).points[1];  // image of (1, 0)
  };
  const auto& poses = plane_keys(scene.panels[0]).poses;
  EXPECT_LT(std::abs(corner(0) - through(homogeneous(poses[0].pose), {1.0, 0.0})), 1e-12);
  EXPECT_LT(std::abs(corner(2) - through(homogeneous(poses[1].pose), {1.0, 0.0})), 1e-12);
  EXPECT_LT(std::abs(corner(3) - through(homogeneous(poses[2].pose), {1.0, 0.0})), 1e-12);
  const Eigen::Matrix3d D =
      homogeneous(poses[1].pose) * homogeneous(poses[0].pose).inverse() * homogeneous(poses[2].pose);
  EXPECT_LT(std::abs(corner(5) - through(D, {1.0, 0.0})), 1e-11);
  plane_keys(scene.panels[0]).poses.resize(2);
  EXPECT_THROW(pose_panel_drawing(scene, scene.panels[0]), RenderError);
}

// Fig. 11: "corner" draws the bottom-right shape, the computed F_D of a
// regular patch, with its own line; every other shape keeps the patch's.
TEST(PoseDrawing, PatchCornerHasItsOwnLine) {
  scene::Scene scene = sam_scene({});
  plane_keys(scene.panels[0]).poses.push_back({3.0, affinity(1.1, 0.2, 0.5, 0.1, 0.9, -3.0)});
  scene::PatchLayer layer;
  layer.columns = 4;
  layer.rows = 3;
  layer.regular = true;
  const scene::Color red{0.9, 0.0, 0.0, 1.0};
  layer.corner = scene::LineStyle{red, 3.5, 1.0, {}};
  scene::figure_of<scene::PlanePoseKeys>(scene).layers = {layer};
  const Drawing drawing = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 12u);
  for (std::size_t k = 0; k < drawing.items.size(); ++k) {
    const scene::LineStyle& line = std::get<Polyline>(drawing.items[k].shape).line;
    const bool corner = k == 11;
    EXPECT_EQ(line.width, corner ? 3.5 : layer.line.width) << k;
    EXPECT_EQ(line.color.r, corner ? red.r : layer.line.color.r) << k;
  }
  const auto& poses = plane_keys(scene.panels[0]).poses;
  const Eigen::Matrix3d D =
      homogeneous(poses[1].pose) * homogeneous(poses[0].pose).inverse() * homogeneous(poses[2].pose);
  EXPECT_LT(std::abs(std::get<Polyline>(drawing.items[11].shape).points[2] - through(D, {0.0, 1.0})), 1e-11);
}

// Fig. 13: "inserted" adds the poses of the last four-point subdivision step,
// which the polySAM through the subdivided poses (PoseMotion) passes through
// at the odd multiples of a quarter of each span after two steps; other
// methods insert nothing.
TEST(PoseDrawing, PosesLayerDrawsTheInsertedPoses) {
  scene::PosesLayer layer;
  layer.colors = {scene::Color{0.8, 0.0, 0.0, 1.0}};
  const scene::Color green{0.0, 0.6, 0.0, 1.0};
  layer.inserted = green;
  scene::Scene scene = sam_scene({layer}, PoseMethod::four_point);
  std::vector<TimedPose> poses = {{0.0, affinity(1.0, 0.0, 0.0, 0.0, 1.0, 0.0)},
                                  {1.0, affinity(0.9, -0.4, 3.0, 0.4, 0.9, 2.0)},
                                  {2.0, affinity(0.6, -0.9, 6.0, 0.8, 0.7, 1.0)},
                                  {3.0, affinity(0.2, -1.2, 8.0, 1.1, 0.1, -1.0)}};
  plane_keys(scene.panels[0]).poses = poses;
  plane_keys(scene.panels[0]).subdivisions = 2;
  const Drawing drawing = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 4u + 6u);
  const PoseMotion motion(PoseMethod::four_point, poses, 2);
  for (std::size_t k = 0; k < 6; ++k) {
    const auto& block = std::get<FilledPath>(drawing.items[k].shape);
    EXPECT_EQ(block.fill.g, green.g);
    const double t = 0.25 + 0.5 * static_cast<double>(k);  // 0.25, 0.75, 1.25, ...
    for (const Point p : {Point{1.0, 0.0}, Point{0.0, 1.0}}) {
      const std::size_t vertex = p.real() > 0.5 ? 1 : 2;
      EXPECT_LT(std::abs(block.contours[0][vertex] - through(homogeneous(motion.at(t)), p)), 1e-12) << t;
    }
  }
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& block = std::get<FilledPath>(drawing.items[6 + i].shape);
    EXPECT_EQ(block.fill.r, 0.8);
    EXPECT_LT(std::abs(block.contours[0][1] - through(homogeneous(poses[i].pose), {1.0, 0.0})), 1e-15);
  }
  plane_keys(scene.panels[0]).method = PoseMethod::poly_sam;
  EXPECT_EQ(pose_panel_drawing(scene, scene.panels[0]).items.size(), 4u);
}

// SAM Figs. 4, 5: "versus" draws another method's motion through the
// panel's poses; with "power" 2 at t = 1/2 the squared mid-way pose X^2 o B.
// On the paper's poses B = Rotate(90 deg), C = Translate(6, 0), Alexa's
// squared mid-way pose is the translation by 12 sqrt(2)/pi (Sec. 3.3.2), the
// SAM's is C; an independent check with Eigen's generic 3x3 log and exp.
TEST(PoseDrawing, VersusLayerDrawsAnotherMethodAndItsPowers) {
  scene::VersusLayer layer;
  layer.method = PoseMethod::alexa;
  layer.at = {0.5};
  layer.power = 2;
  scene::Scene scene = sam_scene({layer});
  const Affine2 B = affinity(0.0, -1.0, 0.0, 1.0, 0.0, 0.0), C = affinity(1.0, 0.0, 6.0, 0.0, 1.0, 0.0);
  plane_keys(scene.panels[0]).poses = {{0.0, B}, {1.0, C}};
  const Drawing squared = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(squared.items.size(), 1u);
  const auto& triangle = std::get<Polyline>(squared.items[0].shape);  // no fill: outlines
  const double shift = 12.0 * std::sqrt(2.0) / kPi;
  EXPECT_LT(std::abs(triangle.points[0] - Point{shift, 0.0}), 1e-13);
  EXPECT_LT(std::abs(triangle.points[1] - Point{shift + 1.0, 0.0}), 1e-13);
  EXPECT_LT(std::abs(triangle.points[2] - Point{shift, 1.0}), 1e-13);
  // Power 1: the mid-way pose e^{(log B + log C)/2}, by Eigen's generic log/exp.
  layer.power = 1;
  scene::figure_of<scene::PlanePoseKeys>(scene).layers = {layer};
  const Drawing middle = pose_panel_drawing(scene, scene.panels[0]);
  const Eigen::Matrix3d expected =
      oracle::exp(Eigen::Matrix3d(0.5 * (oracle::log(homogeneous(B)) + oracle::log(homogeneous(C)))));
  const auto& mid = std::get<Polyline>(middle.items.at(0).shape);
  EXPECT_LT(std::abs(mid.points[1] - through(expected, {1.0, 0.0})), 1e-12);
  // SAM squared at the middle: the last pose.
  layer.method = PoseMethod::sam;
  layer.power = 2;
  scene::figure_of<scene::PlanePoseKeys>(scene).layers = {layer};
  const Drawing sam = pose_panel_drawing(scene, scene.panels[0]);
  EXPECT_LT(std::abs(std::get<Polyline>(sam.items.at(0).shape).points[1] - Point{7.0, 0.0}), 1e-13);
  // Samples over the knots when no "at" is given; a method that needs other
  // pose counts is refused, naming the layer.
  layer.at.clear();
  layer.power = 1;
  scene::figure_of<scene::PlanePoseKeys>(scene).layers = {layer};
  EXPECT_EQ(pose_panel_drawing(scene, scene.panels[0]).items.size(), 5u);
  layer.method = PoseMethod::biarc_sam;
  scene::figure_of<scene::PlanePoseKeys>(scene).layers = {layer};
  try {
    (void)pose_panel_drawing(scene, scene.panels[0]);
    FAIL() << "biarc-SAM takes 3 poses";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("/layers/0"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("method biarc-SAM takes exactly 3 poses (the panel has 2)"),
              std::string::npos)
        << error.what();
  }
}

// A power multiplies the step: (1e30)^16 overflows although every pose is
// finite. Refused at the layer, not drawn with infinities.
TEST(PoseDrawing, VersusLayerPowerThatOverflowsIsRefused) {
  scene::VersusLayer layer;
  layer.method = PoseMethod::sam;
  layer.at = {1.0};
  layer.power = 16;
  scene::Scene scene = sam_scene({layer});
  plane_keys(scene.panels[0]).poses = {{0.0, affinity(1.0, 0.0, 0.0, 0.0, 1.0, 0.0)},
                                       {1.0, affinity(1e30, 0.0, 0.0, 0.0, 1e30, 0.0)}};
  try {
    (void)pose_panel_drawing(scene, scene.panels[0]);
    FAIL() << "a pose of scale 1e480 was drawn";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("/layers/0"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("to the power 16 is not finite"), std::string::npos) << error.what();
  }
  layer.power = 8;  // 1e240: finite, drawn
  scene::figure_of<scene::PlanePoseKeys>(scene).layers = {layer};
  EXPECT_EQ(pose_panel_drawing(scene, scene.panels[0]).items.size(), 1u);
}

// "ara" prints the ARA of the panel's motion. Linear interpolation from the
// identity to the scaling by 2 (over [0, 2]): w(u) = p / (1 + u), so
// |dw/du| = |p| / (1 + u)^2, whose mean over u in [0, 1] is |p| / 2; on the
// 2 x 2 grid of the corners of the box [-1, 1]^2, |p| = sqrt 2: ARA = 0.707.
// A SAM prints 0.
TEST(PoseDrawing, AraLayerPrintsTheMeasuredUnsteadiness) {
  scene::AraLayer layer;
  layer.at = {3.0, -1.0};
  layer.grid = 2;
  scene::Scene scene = sam_scene({layer}, PoseMethod::linear);
  plane_keys(scene.panels[0]).poses = {{0.0, affinity(1.0, 0.0, 0.0, 0.0, 1.0, 0.0)},
                                       {2.0, affinity(2.0, 0.0, 0.0, 0.0, 2.0, 0.0)}};
  scene::figure_of<scene::PlanePoseKeys>(scene.panels[0]).shapes = {
      scene::ShapeOutline{{{-1.0, -1.0}, {1.0, 0.5}, {0.0, 1.0}}, true, std::nullopt, std::nullopt}};
  const Drawing drawing = pose_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 1u);
  const auto& label = std::get<Label>(drawing.items[0].shape);
  EXPECT_EQ(label.text, "ARA = 0.707");
  EXPECT_EQ(label.at, Point(3.0, -1.0));
  const scene::Scene sam = sam_scene({layer}, PoseMethod::sam);
  EXPECT_EQ(std::get<Label>(pose_panel_drawing(sam, sam.panels[0]).items[0].shape).text, "ARA = 0.000");
}

// "swept" (SAM Fig. 10, Sec. 7.2): the printed grazing parameter. For the
// SAM it is checked against the grazing condition solved with Eigen's log of
// the homogeneous matrix (the velocity field x -> log(A) x); for rARAP
// against the characteristic points of the poses alone, where the edge's
// lines at t - h and t + h meet. The drawing has the copies, the ends' paths,
// one envelope run and a path with a dot per instant.
TEST(PoseDrawing, SweptLayerPrintsTheGrazingParameter) {
  const Affine2 last = affinity(-0.6, -0.5, 3.0, 0.45, -0.5, 3.0);
  const Eigen::Vector2d from(-0.6, 1.2), to(2.4, 1.2), d = to - from;
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
  scene::SweptLayer layer;
  layer.edge = {Point(-0.6, 1.2), Point(2.4, 1.2)};
  layer.claim_at = Point(0.0, -1.0);
  layer.trace_samples = 129;
  const auto drawn = [&](PoseMethod method) {
    scene::Scene scene = sam_scene({layer}, method);
    scene::figure_of<scene::PlanePoseKeys>(scene).reference = {Point(-0.6, 0.9), Point(2.4, 0.9), Point(0.9, 1.8)};
    plane_keys(scene.panels[0]).poses = {{0.0, Affine2::identity()}, {1.0, last}};
    return pose_panel_drawing(scene, scene.panels[0]);
  };
  const auto count = [](const Drawing& drawing, auto kind) {
    return std::count_if(drawing.items.begin(), drawing.items.end(),
                         [](const Item& item) { return std::holds_alternative<decltype(kind)>(item.shape); });
  };

  const Drawing sam = drawn(PoseMethod::sam);
  EXPECT_EQ(count(sam, Polyline{}), 5 + 2 + 1 + 3);
  EXPECT_EQ(count(sam, Circle{}), 3);
  ASSERT_EQ(count(sam, Label{}), 1);
  const std::string& text = std::get<Label>(sam.items.back().shape).text;
  double s = 0.0;
  int times = 0;
  ASSERT_EQ(std::sscanf(text.c_str(), "grazing parameter s = %lf at all %d times", &s, &times), 2) << text;
  EXPECT_EQ(times, 129);
  EXPECT_NE(text.find("(spread < 1e-12): constant"), std::string::npos) << text;
  const Eigen::Matrix3d H = oracle::log(homogeneous(last));  // the SAM's velocity field
  const Eigen::Vector2d v0 = H.topLeftCorner<2, 2>() * from + H.topRightCorner<2, 1>();
  const Eigen::Vector2d v1 = H.topLeftCorner<2, 2>() * d;
  EXPECT_NEAR(s, -cross(d, v0) / cross(d, v1), 1e-5);  // printed to 5 decimals

  const Drawing rarap = drawn(PoseMethod::rarap);
  const std::string& moving = std::get<Label>(rarap.items.back().shape).text;
  double low = 0.0, high = 0.0;
  ASSERT_EQ(
      std::sscanf(moving.c_str(), "grazing parameter s ranges from %lf to %lf over %d times", &low, &high, &times), 3)
      << moving;
  EXPECT_EQ(times, 129);
  const PoseMotion motion(PoseMethod::rarap, {{0.0, Affine2::identity()}, {1.0, last}}, 4,
                          {Point(-0.6, 0.9), Point(2.4, 0.9), Point(0.9, 1.8)});
  double expected_low = 1e300, expected_high = -1e300;
  for (int i = 0; i < 129; ++i) {
    const double t = std::clamp(i / 128.0, 1e-5, 1.0 - 1e-5), h = 1e-5;
    const Affine2 P = motion.at(t - h), Q = motion.at(t + h), A = motion.at(t);
    const Eigen::Vector2d p = apply(P, from), dp = P.L * d, q = apply(Q, from), dq = Q.L * d;
    const Eigen::Vector2d meet = p + cross(q - p, dq) / cross(dp, dq) * dp;
    const double here = (meet - apply(A, from)).dot(A.L * d) / (A.L * d).squaredNorm();
    expected_low = std::min(expected_low, here);
    expected_high = std::max(expected_high, here);
  }
  EXPECT_NEAR(low, expected_low, 1e-4);
  EXPECT_NEAR(high, expected_high, 1e-4);
  EXPECT_GT(high - low, 0.3);
}

// Poses of space: the same layers through the camera (render/pose_panel.hpp).

double space_gap(Point a, Point b) { return std::abs(a - b); }

scene::Scene space_scene(const std::string& layers) {
  return scene::parse_scene(R"({"dimension": 3, "method": "SAM", "shapes": [{"solid": "cube"}],
      "camera": {"azimuth": 0, "elevation": 0, "distance": 10, "target": [0, 0, 0]},
      "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
                {"t": 1, "matrix": [[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0]]}],
      "samples": 2, "layers": )" +
                                layers + "}",
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
    EXPECT_LT(space_gap(path.front(), path.back()), 1e-12);
  }
}

// "camera": {"shadow": ...}: each cube drawn casts one shadow, painted
// before every layer: its footprint on the ground, the plane of the lowest
// vertex (z = 0 here, the second pose is lifted by 2), seen by the camera.
// From straight above the shadow of a unit cube is a unit square, wound
// counter-clockwise on the image.
TEST(SpacePanelDrawing, ShadowsLieOnTheGroundUnderEverything) {
  const auto scene_from = [](const std::string& camera) {
    return scene::parse_scene(R"({"dimension": 3, "method": "SAM", "shapes": [{"solid": "cube"}],
      "camera": )" + camera + R"(,
      "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
                {"t": 1, "matrix": [[1, 0, 0, -3], [0, 1, 0, 1], [0, 0, 1, 2]]}],
      "samples": 3, "layers": [{"type": "shapes", "fill": "#808080"}, {"type": "poses"}]})",
                              "s.json");
  };
  const scene::Scene above = scene_from(R"({"elevation": 90, "shadow": "#00000040", "target": [0, 0, 0]})");
  const Drawing drawing = space_panel_drawing(above, above.panels[0]);
  ASSERT_EQ(drawing.items.size(), 5u * (1 + 6));  // 3 frames and 2 poses: a shadow and 6 faces each
  for (std::size_t i = 0; i < drawing.items.size(); ++i) {
    EXPECT_EQ(drawing.items[i].layer == "/camera/shadow", i < 5) << i;
  }
  for (std::size_t i = 0; i < 5; ++i) {
    const FilledPath& shadow = std::get<FilledPath>(drawing.items[i].shape);
    EXPECT_EQ(shadow.fill, (scene::Color{0, 0, 0, 0x40 / 255.0}));
    EXPECT_FALSE(shadow.outline.has_value());
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& contour : shadow.contours) {
      double area = 0.0;
      for (std::size_t k = 0; k < contour.size(); ++k) {
        const Point a = contour[k], b = contour[(k + 1) % contour.size()];
        area += a.real() * b.imag() - b.real() * a.imag();
        x0 = std::min(x0, a.real()), x1 = std::max(x1, a.real());
        y0 = std::min(y0, a.imag()), y1 = std::max(y1, a.imag());
      }
      EXPECT_GT(area, 0.0);
    }
    EXPECT_NEAR(x1 - x0, 1.0, 1e-12) << i;
    EXPECT_NEAR(y1 - y0, 1.0, 1e-12) << i;
  }
  // From the side (+x, up is +z) every shadow lies on the line z = 0 of the
  // image, whatever the height of its cube: it has no area, and is not drawn;
  // from a little above, the lifted cube's shadow is below it on the image.
  const scene::Scene side = scene_from(R"({"azimuth": 0, "elevation": 0, "shadow": true, "target": [0, 0, 0]})");
  EXPECT_EQ(space_panel_drawing(side, side.panels[0]).items.size(), 5u * 6);
  const scene::Scene low = scene_from(R"({"azimuth": 0, "elevation": 20, "shadow": true, "target": [0, 0, 0]})");
  const Drawing seen = space_panel_drawing(low, low.panels[0]);
  ASSERT_EQ(seen.items.size(), 5u * 7);
  const auto lowest = [](const std::vector<std::vector<Point>>& contours) {
    double y = 1e300;
    for (const auto& c : contours) {
      for (const Point p : c) y = std::min(y, p.imag());
    }
    return y;
  };
  const FilledPath& lifted = std::get<FilledPath>(seen.items[4].shape);  // the second pose's
  EXPECT_EQ(seen.items[4].index, 1);
  EXPECT_EQ(lifted.fill.a, 0.14);
  double lifted_bottom = 1e300;
  for (std::size_t i = 5; i < seen.items.size(); ++i) {
    if (seen.items[i].layer != "/layers/1" || seen.items[i].index != 1) continue;
    lifted_bottom = std::min(lifted_bottom, lowest(std::get<FilledPath>(seen.items[i].shape).contours));
  }
  EXPECT_LT(lowest(lifted.contours), lifted_bottom - 1.0);  // 2 up, seen at 20 degrees: cos 20 * 2 lower
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
    corner = corner || space_gap(path.front(), Point(1.0, 1.0)) < 1e-12;
  }
  EXPECT_TRUE(corner);
}

// A velocity arrow per vertex per frame, indexed by the frame: the cube moves
// by -3 along x over the motion, so each arrow is scale x 3 long along x,
// which the camera on the +x axis sees end on (a point).
TEST(SpacePanelDrawing, VelocitiesAreArrowsPerVertexAndFrame) {
  const scene::Scene scene = space_scene(R"([{"type": "velocities", "samples": 3, "scale": 0.5}])");
  const Drawing drawing = space_panel_drawing(scene, scene.panels[0]);
  ASSERT_EQ(drawing.items.size(), 3u * 8u);
  for (std::size_t i = 0; i < drawing.items.size(); ++i) {
    EXPECT_EQ(drawing.items[i].index, static_cast<int>(i / 8)) << i;
    const ArrowShape& arrow = std::get<ArrowShape>(drawing.items[i].shape);
    EXPECT_LT(space_gap(arrow.from, arrow.to), 1e-12) << i;
  }
}

// A layer of the plane only (here a label), in a 3D scene built in code
// rather than read (the reader refuses it), is refused at the layer.
TEST(SpacePanelDrawing, LayerOfThePlaneOnlyIsRefused) {
  scene::Scene scene = space_scene(R"([{"type": "shapes"}])");
  scene::figure_of<scene::SpacePoseKeys>(scene).layers.push_back(scene::LabelLayer{});
  try {
    (void)space_panel_drawing(scene, scene.panels[0]);
    FAIL() << "no error";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("/layers/1: this layer type draws pose scenes of the plane only"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace pita::render
