// The "vectors" and "fixed-points" layers of src/render/panel_drawing.cpp
// (PITA Figs. 9, 14, 15; docs/paper-notes.md N40), checked on the drawn
// shapes themselves: P1's drawn accelerations are all equal, P7's drawn
// accelerations are one similarity of the drawn segments to f (PITA Eq. 35), P8's
// are constant in the drawn frames (PITA Eq. 39), and the placement, colours,
// scale and errors follow the fields.
#include <cmath>
#include <complex>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "render/panel_drawing.hpp"
#include "render_support.hpp"

namespace pita::render {
namespace {

using test::panel;
using test::scene_with;

std::vector<Keyframe> even_keyframes() {
  return {{0.0, Arrow{{0.0, 0.0}, 1.2, 0.9}}, {0.5, Arrow{{3.5, 2.2}, 0.6, 2.6}}, {1.0, Arrow{{6.5, -0.5}, 1.5, 4.0}}};
}

template <typename T>
std::vector<T> shapes_of(const Drawing& drawing) {
  std::vector<T> result;
  for (const Item& item : drawing.items) {
    if (const auto* shape = std::get_if<T>(&item.shape)) result.push_back(*shape);
  }
  return result;
}

Drawing draw(Method method, std::vector<scene::Layer> layers, int samples = 9,
             std::vector<Keyframe> keys = even_keyframes()) {
  const scene::Panel p = panel(method, std::move(keys), samples);
  return panel_drawing(scene_with(std::move(layers), {p}), p);
}

TEST(VectorsLayer, P1AccelerationsAreOneVectorAtEachPoint) {
  scene::VectorsLayer layer;  // accelerations at p (black) and q (brown), from the points
  const std::vector<ArrowShape> arrows = shapes_of<ArrowShape>(draw(Method::P1, {layer}));
  ASSERT_EQ(arrows.size(), 18U);
  // P1's p moves on the Lagrange parabola through u = 0, 1/2, 1: p'' = 4 (pa - 2 pb + pc) per u^2.
  const Vector expected = layer.scale * 4.0 * (Point{0.0, 0.0} - 2.0 * Point{3.5, 2.2} + Point{6.5, -0.5});
  for (std::size_t i = 0; i < arrows.size(); i += 2) {
    EXPECT_LT(std::abs((arrows[i].to - arrows[i].from) - expected), 1e-8) << i;
    EXPECT_EQ(arrows[i].line.color, layer.color_p);
    EXPECT_EQ(arrows[i + 1].line.color, layer.color_q);
  }
}

TEST(VectorsLayer, P7AccelerationsAreOneSimilarityOfTheSegmentsToF) {
  // PITA Eq. 35 on the drawing: each black arrow is S times its orange segment
  // (from p to f), S the same for every frame.
  scene::VectorsLayer vectors;
  vectors.at_q = false;
  scene::FixedPointsLayer segments;
  segments.center = scene::CenterKind::global;
  segments.dots = false;
  const Drawing d = draw(Method::P7, {segments, vectors}, 13);
  const std::vector<Polyline> lines = shapes_of<Polyline>(d);
  const std::vector<ArrowShape> arrows = shapes_of<ArrowShape>(d);
  ASSERT_EQ(lines.size(), 13U);
  ASSERT_EQ(arrows.size(), 13U);
  const Point f = lines[0].points[1];
  Complex S0;
  for (std::size_t i = 0; i < 13; ++i) {
    EXPECT_EQ(lines[i].points[1], f);                                 // one global point
    EXPECT_LT(std::abs(lines[i].points[0] - arrows[i].from), 1e-12);  // both start at D(t).p
    const Complex S = (arrows[i].to - arrows[i].from) / (f - lines[i].points[0]);
    if (i == 0) S0 = S;
    EXPECT_LT(std::abs(S - S0), 1e-7 * std::abs(S0)) << i;
  }
  // The segment to the acceleration center of P7 is the segment to f.
  scene::FixedPointsLayer local = segments;
  local.center = scene::CenterKind::acceleration;
  for (const Polyline& line : shapes_of<Polyline>(draw(Method::P7, {local}, 13))) {
    EXPECT_LT(std::abs(line.points[1] - f), 1e-6 * std::abs(f));
  }
}

TEST(VectorsLayer, P8AccelerationsAreConstantInTheMovingFrame) {
  // Fig. 15's remark: the shapes formed by D(t) and the two accelerations are
  // similar to each other: the accelerations divided by q - p do not change.
  scene::VectorsLayer vectors;
  const Drawing d = draw(Method::P8, {vectors}, 11);
  const std::vector<ArrowShape> arrows = shapes_of<ArrowShape>(d);
  ASSERT_EQ(arrows.size(), 22U);
  Complex first_p, first_q;
  for (std::size_t i = 0; i < arrows.size(); i += 2) {
    const Vector v = arrows[i + 1].from - arrows[i].from;  // q - p
    const Complex local_p = (arrows[i].to - arrows[i].from) / v, local_q = (arrows[i + 1].to - arrows[i + 1].from) / v;
    if (i == 0) first_p = local_p, first_q = local_q;
    EXPECT_LT(std::abs(local_p - first_p), 1e-7 * std::abs(first_p)) << i;
    EXPECT_LT(std::abs(local_q - first_q), 1e-7 * std::abs(first_q)) << i;
  }
}

TEST(VectorsLayer, HeadsArriveOnThePointsAndVelocitiesScale) {
  // P1's velocity of p at u = 0: the parabola's slope (-3 pa + 4 pb - pc) per u.
  scene::VectorsLayer from;
  from.of = scene::VectorKind::velocity;
  from.scale = 0.5;
  from.at_q = false;
  scene::VectorsLayer onto = from;
  onto.tail_at_point = false;
  onto.heads = false;
  const Drawing d = draw(Method::P1, {from, onto}, 2);
  const std::vector<ArrowShape> arrows = shapes_of<ArrowShape>(d);
  const std::vector<Polyline> lines = shapes_of<Polyline>(d);
  ASSERT_EQ(arrows.size(), 2U);
  ASSERT_EQ(lines.size(), 2U);
  const Vector slope = -3.0 * Point{0.0, 0.0} + 4.0 * Point{3.5, 2.2} - Point{6.5, -0.5};
  EXPECT_LT(std::abs(arrows[0].from - Point{0.0, 0.0}), 1e-12);
  EXPECT_LT(std::abs((arrows[0].to - arrows[0].from) - 0.5 * slope), 1e-8);
  // "head": the same vector ends on the point.
  EXPECT_LT(std::abs(lines[0].points[1] - Point{0.0, 0.0}), 1e-12);
  EXPECT_LT(std::abs((lines[0].points[1] - lines[0].points[0]) - 0.5 * slope), 1e-8);
}

TEST(FixedPointsLayer, VelocityCenterOfASteadyMotionIsItsFixedPoint) {
  // With B = M(A, C) and even knots P6 is the steady morph (reading note 14):
  // every frame turns about f = (C.p - l A.p)/(1 - l), l = (mC/mA) e^{i(wC - wA)}.
  const Arrow A{{0.0, 0.0}, 1.0, 0.3}, C{{4.0, 1.0}, 2.0, 2.5};
  const Complex l = std::polar(2.0, 2.2);
  const Point f = (C.p - l * A.p) / (1.0 - l);
  const Complex half = std::polar(std::sqrt(2.0), 1.1);
  const Arrow B{f + half * (A.p - f), std::sqrt(2.0), 1.4};
  scene::FixedPointsLayer layer;
  layer.center = scene::CenterKind::velocity;
  const Drawing d = draw(Method::P6, {layer}, 7, {{0.0, A}, {0.5, B}, {1.0, C}});
  const std::vector<Polyline> lines = shapes_of<Polyline>(d);
  ASSERT_EQ(lines.size(), 7U);
  ASSERT_EQ(shapes_of<Circle>(d).size(), 7U);
  for (const Polyline& line : lines) EXPECT_LT(std::abs(line.points[1] - f), 1e-7);
}

TEST(FixedPointsLayer, NoCenterForATranslatingFrame) {
  // Equal keyframe vectors: kappa = 1, P7 is P1's parabola with f at infinity,
  // and the frame only translates (v' = v'' = 0): no segment is drawn.
  const std::vector<Keyframe> keys = {
      {0.0, Arrow{{0.0, 0.0}, 1.0, 0.5}}, {0.5, Arrow{{2.0, 1.0}, 1.0, 0.5}}, {1.0, Arrow{{4.0, 0.0}, 1.0, 0.5}}};
  for (const scene::CenterKind center :
       {scene::CenterKind::global, scene::CenterKind::acceleration, scene::CenterKind::velocity}) {
    scene::FixedPointsLayer layer;
    layer.center = center;
    EXPECT_TRUE(draw(Method::P7, {layer}, 9, keys).items.empty()) << static_cast<int>(center);
  }
}

TEST(FixedPointsLayer, GlobalIsP7sOnly) {
  scene::FixedPointsLayer layer;
  layer.center = scene::CenterKind::global;
  try {
    draw(Method::P8, {layer});
    FAIL() << "P8 has no global fixed point";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("/layers/0/center"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("P7"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace pita::render
