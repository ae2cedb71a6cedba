// The measures of `pita measure` (src/analysis/measure.cpp), each against an
// independent value: closed forms of circle arcs and Lagrange weights, the
// zeros the papers imply (self-prediction, ARA of a SAM), the pops of Fig. 12
// (tests/core/test_fig10.cpp's configurations) and similarity invariance.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "analysis/measure.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {
namespace {

// The measures of a panel of keyframes, of poses of the plane.
const ArrowMeasures& arrows(const MotionMeasures& m) { return std::get<ArrowMeasures>(m.measured); }
const PoseMeasures<Affine2>& poses(const MotionMeasures& m) { return std::get<PoseMeasures<Affine2>>(m.measured); }

MotionMeasures measure_text(const std::string& text) {
  const scene::Scene scene = scene::parse_scene(text, "test.json");
  const std::vector<MotionMeasures> all = measure_scene(scene);
  EXPECT_EQ(all.size(), 1u);
  return all.front();
}

const ParameterReaction& reaction(const MotionMeasures& m, const std::string& name) {
  for (const ParameterReaction& r : parameters_of(m)) {
    if (r.name == name) return r;
  }
  ADD_FAILURE() << "no parameter " << name;
  static const ParameterReaction none;
  return none;
}

TEST(Measure, SteadyRotationTracesCircleArcs) {
  // B is A rotated by theta about the origin: the steady morph is that
  // rotation, so p runs on the circle of radius |A.p| through theta, q on the
  // circle of radius |A.q|; both turn by theta.
  const double theta = 2.0;
  const Arrow A{{2.0, 0.0}, 1.0, kPi / 2};
  const Complex turn = std::polar(1.0, theta);
  const Arrow B{A.p * turn, 1.0, A.w + theta};
  const MotionMeasures m = measure_text(fmt::format(
      R"({{"method": "SMA", "keyframes": [{{"t": 0, "p": [{}, {}], "m": 1, "w": {}}},
          {{"t": 1, "p": [{}, {}], "m": 1, "w": {}}}]}})",
      A.p.real(), A.p.imag(), A.w, B.p.real(), B.p.imag(), B.w));
  ASSERT_FALSE(m.no_motion) << *m.no_motion;
  ASSERT_FALSE(m.no_motion);
  ASSERT_TRUE(std::holds_alternative<ArrowMeasures>(m.measured));
  EXPECT_NEAR(arrows(m).path_p.length, 2.0 * theta, 1e-5);  // chords: O(h^2)
  EXPECT_NEAR(arrows(m).path_q.length, std::sqrt(5.0) * theta, 1e-5);
  EXPECT_NEAR(arrows(m).path_p.turning, theta, 1e-9);
  EXPECT_NEAR(arrows(m).path_q.turning, theta, 1e-9);
  EXPECT_EQ(arrows(m).path_p.inflections, 0);
  EXPECT_NEAR(arrows(m).winding_min, A.w, 1e-12);
  EXPECT_NEAR(arrows(m).winding_max, B.w, 1e-12);
  // The steady average of the neighbours is the frame itself (PITA Eq. 23).
  ASSERT_EQ(arrows(m).discrepancy.size(), 3u);
  EXPECT_EQ(arrows(m).discrepancy[1].predictor, "average");
  EXPECT_LT(arrows(m).discrepancy[1].max, 1e-20);
}

TEST(Measure, CollinearParabolaDoesNotTurn) {
  // P1 with p and q on one line, p monotone (x(t) = 2t^2 + t): no turning.
  const MotionMeasures m = measure_text(R"({"method": "P1", "keyframes": [
      {"t": 0,   "p": [0, 0], "q": [0.5, 0.5]},
      {"t": 0.5, "p": [1, 1], "q": [2, 2]},
      {"t": 1,   "p": [3, 3], "q": [4.5, 4.5]}]})");
  ASSERT_FALSE(m.no_motion);
  // q = p + m e^{iw} with w = pi/4 rounds off the line by ~1e-16: turning to rounding.
  EXPECT_LT(arrows(m).path_p.turning, 1e-9);
  EXPECT_LT(arrows(m).path_q.turning, 1e-9);
  // Its turns of rounding's size, either way, are no inflections.
  EXPECT_EQ(arrows(m).path_p.inflections, 0);
  EXPECT_EQ(arrows(m).path_q.inflections, 0);
  EXPECT_NEAR(arrows(m).path_p.length, 3.0 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(arrows(m).path_q.length, 4.0 * std::sqrt(2.0), 1e-9);
}

// A curve sampled as path_stats takes it: n + 1 parameters evenly over
// [a, b], and one step beyond each end.
std::vector<Point> sampled(double a, double b, int n, const auto& curve) {
  std::vector<Point> points;
  const double h = (b - a) / n;
  for (int i = -1; i <= n + 1; ++i) points.push_back(curve(a + h * i));
  return points;
}

TEST(Measure, InflectionsAreTheSignChangesOfTheCurvature) {
  // Curvature x'y'' - y'x'' of (x, f(x)) is f'': its sign changes where f''
  // does (Sec. 6.5: P1's parabola and P2's log spiral have none).
  const auto graph = [](auto f) { return [f](double x) { return Point{x, f(x)}; }; };
  EXPECT_EQ(path_stats(sampled(-1, 1, 2048, graph([](double x) { return x * x; }))).inflections, 0);
  EXPECT_EQ(path_stats(sampled(-1, 1, 2048, graph([](double x) { return x * x * x; }))).inflections, 1);
  // sin'' = -sin changes sign at pi and 2 pi inside (0.1, 3 pi - 0.1).
  EXPECT_EQ(path_stats(sampled(0.1, 3 * kPi - 0.1, 2048, graph([](double x) { return std::sin(x); }))).inflections, 2);
  // A circle arc and a log spiral turn one way only; a segment not at all.
  EXPECT_EQ(path_stats(sampled(0, 5, 2048, [](double t) { return std::polar(2.0, t); })).inflections, 0);
  EXPECT_EQ(path_stats(sampled(0, 9, 2048, [](double t) { return std::exp(Complex{0.2, 1.0} * t); })).inflections, 0);
  EXPECT_EQ(path_stats(sampled(0, 1, 2048, [](double t) { return Point{3.0 * t, 1.0 + t}; })).inflections, 0);
}

TEST(Measure, MethodPredictsItselfWhereItIsQuadratic) {
  // P1 and P3 are quadratic in t (Lagrange): three of their own frames give
  // back the next one, so the "pita" predictor's discrepancy vanishes, while
  // the previous frame does not.
  for (const char* method : {"P1", "P3"}) {
    const MotionMeasures m = measure_text(fmt::format(R"({{"method": "{}", "samples": 17, "keyframes": [
        {{"t": 0, "p": [0, 0], "m": 1, "w": 0.4}}, {{"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0}},
        {{"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}}]}})",
                                                      method));
    ASSERT_FALSE(m.no_motion);
    EXPECT_EQ(arrows(m).discrepancy[2].predictor, "pita");
    EXPECT_EQ(arrows(m).discrepancy[2].frames, 17 - 3);
    EXPECT_LT(arrows(m).discrepancy[2].max, 1e-12) << method;
    EXPECT_EQ(arrows(m).discrepancy[0].frames, 16);
    EXPECT_GT(arrows(m).discrepancy[0].max, 0.1) << method;
  }
}

TEST(Measure, TranslationGainOfP1IsTheLagrangeWeightBound) {
  // P1 moves p and q by L_b(t) delta when B is translated (or when B.q moves,
  // by -Ca): the gain is max over [a, c] of the middle Lagrange weight,
  // (c - a)^2 / (4 (b - a)(c - b)) at t = (a + c)/2: 1.5625 for b = 0.8.
  // A's weight is at most 1 on [a, c] (at t = a).
  const MotionMeasures m = measure_text(R"({"method": "P1", "keyframes": [
      {"t": 0,   "p": [0, 0], "m": 1, "w": 0.4},
      {"t": 0.8, "p": [3, 1.5], "m": 0.6, "w": 2.0},
      {"t": 1,   "p": [6, 0], "m": 1.2, "w": 3.5}]})");
  ASSERT_FALSE(m.no_motion);
  const double bound = 1.0 / (4.0 * 0.8 * 0.2);
  EXPECT_NEAR(reaction(m, "B.p.x").gain, bound, 1e-6);
  EXPECT_NEAR(reaction(m, "B.p.y").gain, bound, 1e-6);
  EXPECT_NEAR(reaction(m, "B.q.x").gain, bound, 1e-6);
  EXPECT_NEAR(reaction(m, "A.p.x").gain, 1.0, 1e-6);
  EXPECT_EQ(arrows(m).parameters.size(), 21u);
  EXPECT_FALSE(arrows(m).pops);
}

TEST(Measure, GainsAreSimilarityInvariant) {
  // The same keyframes rotated by 0.7, scaled by 3 and moved: same gains.
  const auto scene_of = [](Complex scale, Complex shift) {
    std::string keys;
    const Arrow keyframes[3] = {{{0, 0}, 1, 0.4}, {{3, 1.5}, 0.6, 2.0}, {{6, 0}, 1.2, 3.5}};
    const double knots[3] = {0, 0.6, 1};
    for (int i = 0; i < 3; ++i) {
      const Complex p = keyframes[i].p * scale + shift;
      keys += fmt::format(R"({}{{"t": {}, "p": [{}, {}], "m": {}, "w": {}}})", i ? "," : "", knots[i], p.real(),
                          p.imag(), keyframes[i].m * std::abs(scale), keyframes[i].w + std::arg(scale));
    }
    return measure_text(R"({"method": "P6", "keyframes": [)" + keys + "]}");
  };
  const MotionMeasures a = scene_of(1.0, 0.0), b = scene_of(std::polar(3.0, 0.7), Complex{5, -2});
  ASSERT_EQ(arrows(a).parameters.size(), arrows(b).parameters.size());
  EXPECT_NEAR(arrows(b).extent, 3.0 * arrows(a).extent, 1e-9);
  // q.x and q.y mix under a rotation; p.x, p.y too: compare the larger of each pair.
  for (std::size_t i = 0; i < arrows(a).parameters.size(); ++i) {
    const std::string& name = arrows(a).parameters[i].name;
    if (name.find(".p.") != std::string::npos || name.find(".q.") != std::string::npos) continue;
    const double gain = arrows(a).parameters[i].gain;
    EXPECT_NEAR(gain, arrows(b).parameters[i].gain, 1e-5 * gain) << name;
  }
  EXPECT_NEAR(arrows(a).path_p.turning, arrows(b).path_p.turning, 1e-9);
  EXPECT_NEAR(arrows(b).path_q.length, 3.0 * arrows(a).path_q.length, 1e-9);
  EXPECT_NEAR(arrows(a).discrepancy[0].max, arrows(b).discrepancy[0].max, 1e-9);
}

// tests/core/test_fig10.cpp pop_config(0, 0): a, b, c collinear with c
// behind b, Arg((c - b)/(b - a)) = pi: LS- (P2) pops under a tweak of C.p.y.
const char* kP2PopKeyframes = R"("keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 1}, {"t": 0.5, "p": [2, 0], "m": 0.8, "w": 1.6},
    {"t": 1, "p": [0.5, 0], "m": 1.2, "w": 2.2}])";

TEST(Measure, PopOfP2AtItsBranchCutNoneForP6) {
  const MotionMeasures p2 = measure_text(std::string(R"({"method": "P2", )") + kP2PopKeyframes + "}");
  ASSERT_FALSE(p2.no_motion);
  EXPECT_TRUE(arrows(p2).pops);
  // Moving c or b off the line flips the principal angle between pi and -pi.
  EXPECT_TRUE(reaction(p2, "C.p.y").pop);
  EXPECT_GT(reaction(p2, "C.p.y").jump, 1e-2);  // O(1), not O(1e-9)
  EXPECT_TRUE(reaction(p2, "B.p.y").pop);
  EXPECT_FALSE(reaction(p2, "C.p.x").pop);

  const MotionMeasures p6 = measure_text(std::string(R"({"method": "P6", )") + kP2PopKeyframes + "}");
  EXPECT_FALSE(arrows(p6).pops);
  for (const ParameterReaction& r : arrows(p6).parameters) {
    EXPECT_LT(r.jump, 1e-6) << r.name;
    EXPECT_FALSE(r.pop) << r.name;
  }
}

TEST(Measure, PopOfP8AtTheCutOfAcosh) {
  // pop_config(2, 0): (vA + vC)/(2 vB) = -1.5 real, on the cut of acosh.
  const MotionMeasures p8 = measure_text(R"({"method": "P8", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1.5, "w": 3.141592653589793}, {"t": 0.5, "p": [2, 1], "m": 1, "w": 0},
      {"t": 1, "p": [4, 0], "m": 1.5, "w": 3.141592653589793}]})");
  ASSERT_FALSE(p8.no_motion) << *p8.no_motion;
  EXPECT_TRUE(arrows(p8).pops);
}

TEST(Measure, PoseMotionsAraAndArea) {
  // From I to the rotation by theta = 3: the SAM is that rotation (det 1
  // throughout, ARA 0); linear interpolation has det((1-t) I + t R) =
  // (1-t)^2 + t^2 + 2t(1-t) cos theta, lowest at t = 1/2: an excursion of
  // (1 - cos theta)/2 below the constant 1.
  const double theta = 3.0, c = std::cos(theta), s = std::sin(theta);
  const auto scene_text = [&](const char* method) {
    return fmt::format(R"({{"method": "{}", "poses": [{{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}},
        {{"t": 1, "matrix": [[{}, {}, 2], [{}, {}, 1]]}}]}})",
                       method, c, -s, s, c);
  };
  const MotionMeasures sam = measure_text(scene_text("SAM"));
  ASSERT_FALSE(sam.no_motion) << *sam.no_motion;
  EXPECT_LT(poses(sam).ara, 1e-6);
  EXPECT_TRUE(poses(sam).area.monotone);
  const MotionMeasures linear = measure_text(scene_text("linear"));
  EXPECT_GT(poses(linear).ara, 0.1);
  EXPECT_FALSE(poses(linear).area.monotone);
  EXPECT_NEAR(poses(linear).area.excursion, (1.0 - c) / 2.0, 1e-9);
  EXPECT_NEAR(poses(linear).area.t_of_excursion, 0.5, 1e-12);
}

// The velocity jump: a polySAM of two translations, by (1, 0) then by (0, 1),
// turns every point's velocity from (1, 0) to (0, 1) at t = 1 (a sample:
// 2048 over [0, 2]): a jump of sqrt 2 at the mean speed 1. One translation
// does not jump, and the SAM of a rotation (smooth) by about one step's angle.
TEST(Measure, VelocityJumpOfAPolySamAtItsMiddlePose) {
  const MotionMeasures two = measure_text(R"({"method": "polySAM",
      "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[1, 0, 1], [0, 1, 0]]},
                {"t": 2, "matrix": [[1, 0, 1], [0, 1, 1]]}]})");
  ASSERT_FALSE(two.no_motion) << *two.no_motion;
  ASSERT_TRUE(std::holds_alternative<PoseMeasures<Affine2>>(two.measured));
  EXPECT_NEAR(poses(two).velocity_jump, std::sqrt(2.0), 1e-9);
  const MotionMeasures one = measure_text(R"({"method": "SAM",
      "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[1, 0, 1], [0, 1, 0]]}]})");
  EXPECT_LT(poses(one).velocity_jump, 1e-9);
  const MotionMeasures turn = measure_text(R"({"method": "SAM",
      "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0, -1, 0], [1, 0, 0]]}]})");
  // A point at radius r: chords of 2 r sin(phi / 2), each turned by phi = (pi / 2) / 2048 from
  // the last: a jump of 2 sin(phi / 2) times the farthest point's radius over the mean one.
  const double phi = M_PI / 2.0 / 2048.0;
  EXPECT_GT(poses(turn).velocity_jump, 2.0 * std::sin(phi / 2.0));
  EXPECT_LT(poses(turn).velocity_jump, 4.0 * phi);
}

// The ARA that pita measure (and claims) report is the one an "ara" layer
// prints: over the default grid of the box of the panel's shapes. Linear
// interpolation from the identity to the scaling by 2: |dw/du| = |p| / (1 + u)^2,
// whose mean over u in [0, 1] is |p| / 2; averaged over the 11 x 11 grid of
// [-1, 1]^2 (its mean |p|, computed here point by point).
TEST(Measure, AraIsTheFiguresOverTheGridOfTheShapesBox) {
  const MotionMeasures linear = measure_text(R"({"method": "linear",
      "shapes": [{"polygon": [[-1, -1], [1, -1], [1, 1], [-1, 1]]}],
      "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}]})");
  double mean = 0.0;
  for (int i = 0; i < 11; ++i) {
    for (int j = 0; j < 11; ++j) mean += std::hypot(-1.0 + 0.2 * i, -1.0 + 0.2 * j) / 121.0;
  }
  ASSERT_FALSE(linear.no_motion) << *linear.no_motion;
  EXPECT_NEAR(poses(linear).ara, mean / 2.0, 1e-4);
}

TEST(Measure, AreaStatsOfMonotoneAndDippingSequences) {
  EXPECT_TRUE(area_stats({0, 1, 2, 3}, {1, 2, 2, 5}).monotone);
  EXPECT_TRUE(area_stats({0, 1, 2}, {3, 2, 1}).monotone);
  const AreaStats dip = area_stats({0, 1, 2, 3}, {1, 4, 2, 5});
  EXPECT_FALSE(dip.monotone);
  EXPECT_DOUBLE_EQ(dip.excursion, 2.0 / 5.0);  // from 4 down to 2, relative to max 5
  EXPECT_EQ(dip.t_of_excursion, 2.0);
}

TEST(Measure, NoMotionIsReportedNotThrown) {
  // P7 with (vA + vC)/(2 vB) = -1 exactly: no solution (docs/paper-notes.md N13).
  const MotionMeasures m = measure_text(R"({"method": "P7", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 3.141592653589793}, {"t": 0.5, "p": [2, 1], "m": 1, "w": 0},
      {"t": 1, "p": [4, 0], "m": 1, "w": 3.141592653589793}]})");
  ASSERT_TRUE(m.no_motion.has_value());
  EXPECT_NE(m.no_motion->find("test.json"), std::string::npos) << *m.no_motion;
  EXPECT_TRUE(parameters_of(m).empty());
  ASSERT_TRUE(std::holds_alternative<ArrowMeasures>(m.measured));  // its kind, nothing measured
  EXPECT_EQ(arrows(m).path_p.length, 0.0);
  EXPECT_EQ(measured_kind_name(m), "arrows");
}

MotionMeasures with_measures(KindMeasures measured) {
  MotionMeasures m;
  m.measured = std::move(measured);
  return m;
}

// The kind's name as `pita measure` prints it, and the tweaked parameters (of keyframes only).
TEST(Measure, KindNameAndParametersOfEachKind) {
  ArrowMeasures arrow_numbers;
  arrow_numbers.parameters = {{.name = "A.p.x"}, {.name = "A.p.y"}};
  const MotionMeasures keyframes = with_measures(arrow_numbers);
  EXPECT_EQ(measured_kind_name(keyframes), "arrows");
  ASSERT_EQ(parameters_of(keyframes).size(), 2u);
  EXPECT_EQ(parameters_of(keyframes)[1].name, "A.p.y");
  const MotionMeasures points = with_measures(PointMeasures{});
  const MotionMeasures plane = with_measures(PoseMeasures<Affine2>{});
  const MotionMeasures space = with_measures(PoseMeasures<Affine3>{});
  EXPECT_EQ(measured_kind_name(points), "points");
  EXPECT_EQ(measured_kind_name(plane), "poses");
  EXPECT_EQ(measured_kind_name(space), "poses3d");
  for (const MotionMeasures* m : {&points, &plane, &space}) EXPECT_TRUE(parameters_of(*m).empty());
  EXPECT_EQ(PoseMeasures<Affine2>::det_name, "area");
  EXPECT_EQ(PoseMeasures<Affine3>::det_name, "volume");
}

TEST(Measure, ExtentIsTheDiameterOfTheEndpoints) {
  const std::vector<Keyframe> keys{{0, {{0, 0}, 1, 0}}, {1, {{3, 4}, 1, kPi / 2}}};
  // Endpoints (0,0), (1,0), (3,4), (3,5): the farthest pair is (0,0)-(3,5).
  EXPECT_DOUBLE_EQ(keyframe_extent(keys), std::sqrt(34.0));
}

}  // namespace
}  // namespace pita::analysis

namespace pita::analysis {
namespace {

TEST(Measure, TurnGainOfShortFramesOfP1) {
  // Fig. 19: -Ca interpolates the vectors v(t) = sum L_i(t) v_i; moving B.q
  // up by delta adds L_b(t) (0, delta) to v(t), which turns it by
  // L_b v_x delta / |v|^2. With v_A = v_C = (0, 2.4), v_B = (0.15, -0.8) the
  // frames near t = 1/4 and 3/4 are short and turn fast.
  const MotionMeasures m = measure_text(R"({"method": "P1", "keyframes": [
      {"t": 0, "p": [0, 0], "q": [0, 2.4]}, {"t": 0.5, "p": [3, 1], "q": [3.15, 0.2]},
      {"t": 1, "p": [6, 0], "q": [6, 2.4]}]})");
  ASSERT_FALSE(m.no_motion);
  const double extent = std::hypot(6.0, 2.4);  // from A.p to C.q
  EXPECT_NEAR(arrows(m).extent, extent, 1e-12);
  double expected = 0.0;
  for (int i = 0; i <= 64; ++i) {
    const double t = i / 64.0;
    const double la = (t - 0.5) * (t - 1.0) / 0.5, lb = -t * (t - 1.0) / 0.25, lc = t * (t - 0.5) / 0.5;
    const Complex v = la * Complex{0, 2.4} + lb * Complex{0.15, -0.8} + lc * Complex{0, 2.4};
    expected = std::max(expected, std::abs(lb * v.real()) / std::norm(v) * extent);
  }
  EXPECT_GT(expected, 40.0);  // 0.75 / 0.1125 x extent at t = 1/4
  EXPECT_NEAR(reaction(m, "B.q.y").turn, expected, 1e-4 * expected);
  // The frames themselves move little: B's Lagrange weight, at most 1.
  EXPECT_NEAR(reaction(m, "B.q.y").gain, 1.0, 1e-6);
}

}  // namespace
}  // namespace pita::analysis
