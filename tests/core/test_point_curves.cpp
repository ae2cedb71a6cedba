// Point curves through n timed points (src/core/point_curves.cpp; PITA
// Sec. 7.6, PITA Eq. 48-50, Fig. 29): the PITA-based curve, uniform and
// centripetal Neville, and the log-spiral blend.
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/limits.hpp"
#include "core/point_curves.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

// Paper knots of Sec. 7.6: p(0) = a, p(1/3) = b, p(2/3) = c, p(1) = d.
constexpr std::array<double, 4> kPaperKnots{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};

// n random points, consecutive ones at least `gap` apart, at the given knots.
std::vector<TimedPoint> random_points(Sampler& s, const std::vector<double>& knots, double gap = 0.5) {
  std::vector<TimedPoint> out;
  for (const double t : knots) {
    Point p = s.point();
    while (!out.empty() && std::abs(p - out.back().p) < gap) p = s.point();
    out.push_back({t, p});
  }
  return out;
}

std::vector<double> paper_knots() { return {kPaperKnots.begin(), kPaperKnots.end()}; }

// n strictly increasing random knots from a random start.
std::vector<double> random_knots(Sampler& s, int n) {
  std::vector<double> knots{s.uniform(-2.0, 2.0)};
  for (int i = 1; i < n; ++i) knots.push_back(knots.back() + std::exp(s.uniform(-1.5, 1.0)));
  return knots;
}

// n knots with steps within a factor 1.25 of each other (Fig. 29's are even).
// The log-spiral blend needs them to stay well conditioned: with very uneven
// knots the quadratic time map of LS- (u = y + 2z, PITA Eq. 26) reaches large |u|
// at knots far from a triple's own, where that triple's spiral may be 1e10
// times the size of the points, and the blend's polynomial weights, though
// they vanish at the knots, keep a share of it between them: the curve itself
// is then huge and its rounding errors with it.
std::vector<double> nearly_even_knots(Sampler& s, int n) {
  std::vector<double> knots{s.uniform(-2.0, 2.0)};
  const double step = std::exp(s.uniform(-1.0, 1.0));
  for (int i = 1; i < n; ++i) knots.push_back(knots.back() + step * std::exp(s.uniform(-0.22, 0.22)));
  return knots;
}

// The size of a point set: distances are compared to it.
double extent(const std::vector<TimedPoint>& points) {
  double e = 0.0;
  for (const TimedPoint& x : points) {
    for (const TimedPoint& y : points) e = std::max(e, std::abs(x.p - y.p));
  }
  return e;
}

// Times to compare curves at: between and beyond the knots, never on one.
std::vector<double> between_times(const std::vector<TimedPoint>& points) {
  std::vector<double> ts;
  const double t0 = points.front().t, t1 = points.back().t;
  for (int i = 0; i <= 40; ++i) ts.push_back(t0 + (t1 - t0) * (-0.2 + 1.4 * (i + 0.37) / 40.0));
  return ts;
}

ArrowTrackFactory pita_track(Method m) {
  return [m](std::span<const Keyframe> k) { return make_motion(m, k); };
}

// Says where a curve misses its point: which point, by how much of the extent.
::testing::AssertionResult passes_through_points(const PointCurveMotion& curve, double tol) {
  const std::vector<TimedPoint>& points = curve.points();
  const double e = extent(points);
  std::string what;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = std::abs(curve.at(points[i].t) - points[i].p) / e;
    if (!(d <= tol)) what += " point " + std::to_string(i) + " missed by " + std::to_string(d) + " (relative)";
  }
  if (what.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << info(curve.curve()).name << ":" << what;
}

// ------------------------------------------------------------------ table

TEST(PointCurveTable, NamesFindTheirCurves) {
  ASSERT_EQ(all_point_curves().size(), 4u);
  const std::array<std::pair<PointCurve, std::string_view>, 4> expected{{
      {PointCurve::pita, "pita"},
      {PointCurve::neville_uniform, "neville-uniform"},
      {PointCurve::neville_centripetal, "neville-centripetal"},
      {PointCurve::log_spiral_blend, "log-spiral-blend"},
  }};
  for (const auto& [curve, name] : expected) {
    const PointCurveInfo* found = find_point_curve(name);
    ASSERT_NE(found, nullptr) << name;
    EXPECT_EQ(found->curve, curve) << name;
    EXPECT_EQ(info(curve).name, name);
    EXPECT_FALSE(info(curve).title.empty()) << name;
  }
  EXPECT_EQ(find_point_curve("PITA"), nullptr);  // exact names only
  EXPECT_EQ(find_point_curve("neville"), nullptr);
  EXPECT_EQ(find_point_curve(""), nullptr);
}

// ------------------------------------------------------------------ pita

// PITA Eq. 48-50's four conditions p(0) = a, p(1/3) = b, p(2/3) = c, p(1) = d with
// each PITA as the track.
TEST(PointCurvePita, MeetsTheFourConditionsOfEq48To50ForEveryPita) {
  for (const Method m : pitas()) {
    Sampler s(4800 + static_cast<int>(m));
    for (int i = 0; i < 20; ++i) {
      const PointCurveMotion curve(PointCurve::pita, random_points(s, paper_knots()), pita_track(m));
      EXPECT_TRUE(passes_through_points(curve, 1e-9)) << name(m) << " #" << i;
    }
  }
}

// PITA Eq. 48-50 written out: X = P_x(0, ab, 1/3, bc, 2/3, cd, t),
// Y = P_x(1/3, ab, 2/3, bc, 1, cd, t), p = (1 - t) X.p + t Y.q, the edges
// winding as the shape turns: bc turns from ab, and cd from bc, by the
// principal angle between them (docs/paper-notes.md N34).
TEST(PointCurvePita, IsEq48To50WrittenOut) {
  for (const Method m : pitas()) {
    Sampler s(5000 + static_cast<int>(m));
    for (int i = 0; i < 5; ++i) {
      const std::vector<TimedPoint> points = random_points(s, paper_knots());
      const Point a = points[0].p, b = points[1].p, c = points[2].p, d = points[3].p;
      const auto edge = [](Point from, Point to) { return Arrow{from, std::abs(to - from), std::arg(to - from)}; };
      Arrow ab = edge(a, b), bc = edge(b, c), cd = edge(c, d);
      bc.w = ab.w + std::remainder(bc.w - ab.w, 2.0 * kPi);
      cd.w = bc.w + std::remainder(cd.w - bc.w, 2.0 * kPi);
      const auto X = make_pita(m, {{0.0, ab}, {1.0 / 3.0, bc}, {2.0 / 3.0, cd}});
      const auto Y = make_pita(m, {{1.0 / 3.0, ab}, {2.0 / 3.0, bc}, {1.0, cd}});
      const PointCurveMotion curve(PointCurve::pita, points, pita_track(m));
      const double e = extent(points);
      for (const double t : between_times(points)) {
        const Point expected = (1.0 - t) * X->at(t).p + t * Y->at(t).q();
        EXPECT_NEAR(std::abs(curve.at(t) - expected) / e, 0.0, 1e-12) << name(m) << " #" << i << " t=" << t;
      }
    }
  }
}

// A track through any number of keyframes: p and the vector each move on the
// polyline through their keyframe values (linear in t per span, continued
// beyond the ends).
class PolylineTrack : public Motion {
 public:
  explicit PolylineTrack(std::span<const Keyframe> k) : k_(k.begin(), k.end()) {}
  Arrow at(double t) const override {
    std::size_t i = 0;
    while (i + 2 < k_.size() && t > k_[i + 1].t) ++i;
    const double s = (t - k_[i].t) / (k_[i + 1].t - k_[i].t);
    const Point p = k_[i].arrow.p + s * (k_[i + 1].arrow.p - k_[i].arrow.p);
    const Vector v = k_[i].arrow.vector() + s * (k_[i + 1].arrow.vector() - k_[i].arrow.vector());
    return arrow_from_vector(p, v);
  }

 private:
  std::vector<Keyframe> k_;
};

// n points, n - 1 edge arrows per track: through every point at its knot, and
// at s = 0 and s = 1 the ends of the two tracks' edges.
TEST(PointCurvePita, GeneralisesToNPointsWithAnyTrack) {
  const ArrowTrackFactory polyline = [](std::span<const Keyframe> k) -> std::unique_ptr<Motion> {
    return std::make_unique<PolylineTrack>(k);
  };
  Sampler s(4900);
  for (int n = 4; n <= 9; ++n) {
    for (int i = 0; i < 5; ++i) {
      const std::vector<TimedPoint> points = random_points(s, random_knots(s, n));
      const PointCurveMotion curve(PointCurve::pita, points, polyline);
      EXPECT_TRUE(passes_through_points(curve, 1e-12)) << "n=" << n << " #" << i;
      // Midway in the first span, s = (t - t_0)/(t_{n-1} - t_0): the blend of
      // X's start point (on the segment p_0 p_1) and Y's end point.
      const double t = 0.5 * (points[0].t + points[1].t);
      const double w = (t - points[0].t) / (points.back().t - points[0].t);
      const Point x_start = 0.5 * (points[0].p + points[1].p);
      const Vector y_first = points[1].p - points[0].p, y_second = points[2].p - points[1].p;
      const double r = (t - points[1].t) / (points[2].t - points[1].t);  // Y extrapolates back
      const Point y_end = points[0].p + r * (points[1].p - points[0].p) + y_first + r * (y_second - y_first);
      EXPECT_NEAR(std::abs(curve.at(t) - ((1.0 - w) * x_start + w * y_end)) / extent(points), 0.0, 1e-12);
    }
  }
}

// ------------------------------------------------------------------ Neville

// The cubic Lagrange polynomial through (u_i, p_i), basis written out.
Point lagrange_cubic(const std::array<double, 4>& u, const std::array<Point, 4>& p, double x) {
  const double l0 = (x - u[1]) * (x - u[2]) * (x - u[3]) / ((u[0] - u[1]) * (u[0] - u[2]) * (u[0] - u[3]));
  const double l1 = (x - u[0]) * (x - u[2]) * (x - u[3]) / ((u[1] - u[0]) * (u[1] - u[2]) * (u[1] - u[3]));
  const double l2 = (x - u[0]) * (x - u[1]) * (x - u[3]) / ((u[2] - u[0]) * (u[2] - u[1]) * (u[2] - u[3]));
  const double l3 = (x - u[0]) * (x - u[1]) * (x - u[2]) / ((u[3] - u[0]) * (u[3] - u[1]) * (u[3] - u[2]));
  return l0 * p[0] + l1 * p[1] + l2 * p[2] + l3 * p[3];
}

// The scene-time to parameter map of 4 points, by cases: first span (and
// before it), middle span, last span (and after it).
double four_point_parameter(const std::array<double, 4>& t, const std::array<double, 4>& u, double x) {
  if (x < t[1]) return u[0] + (x - t[0]) * (u[1] - u[0]) / (t[1] - t[0]);
  if (x < t[2]) return u[1] + (x - t[1]) * (u[2] - u[1]) / (t[2] - t[1]);
  return u[2] + (x - t[2]) * (u[3] - u[2]) / (t[3] - t[2]);
}

TEST(PointCurveNevilleUniform, IsTheCubicLagrangePolynomialInTheParameter) {
  Sampler s(5100);
  for (int i = 0; i < 10; ++i) {
    const std::vector<double> knots = i == 0 ? paper_knots() : random_knots(s, 4);
    const std::vector<TimedPoint> points = random_points(s, knots);
    const PointCurveMotion curve(PointCurve::neville_uniform, points);
    const std::array<double, 4> t{knots[0], knots[1], knots[2], knots[3]};
    const std::array<Point, 4> p{points[0].p, points[1].p, points[2].p, points[3].p};
    const std::array<double, 4> u{0.0, 1.0, 2.0, 3.0};
    const double e = extent(points);
    for (const double x : between_times(points)) {
      const Point expected = lagrange_cubic(u, p, four_point_parameter(t, u, x));
      EXPECT_NEAR(std::abs(curve.at(x) - expected) / e, 0.0, 1e-12) << "#" << i << " t=" << x;
      // At the paper's even knots u = 3t: the cubic through the points in time.
      if (i == 0) {
        EXPECT_NEAR(std::abs(curve.at(x) - lagrange_cubic(t, p, x)) / e, 0.0, 1e-12) << x;
      }
    }
  }
}

TEST(PointCurveNeville, PassesThroughEveryPointForFourToTwelvePoints) {
  Sampler s(5200);
  for (const PointCurve c : {PointCurve::neville_uniform, PointCurve::neville_centripetal}) {
    for (int n = 4; n <= 12; ++n) {
      for (int i = 0; i < 5; ++i) {
        const PointCurveMotion curve(c, random_points(s, random_knots(s, n)));
        EXPECT_TRUE(passes_through_points(curve, 1e-9)) << "n=" << n << " #" << i;
      }
    }
  }
}

// Collinear points 0, 1, 5, 6 (steps 1, 4, 1): centripetal parameters
// 0, 1, 3, 4, uniform ones 0, 1, 2, 3.
TEST(PointCurveNevilleCentripetal, ParameterStepsAreSquareRootsOfDistances) {
  const Point origin{1.0, -2.0};
  const Vector direction = std::polar(1.0, 0.4);
  const std::array<double, 4> t{0.0, 0.25, 0.5, 1.5};
  const std::array<Point, 4> p{origin, origin + 1.0 * direction, origin + 5.0 * direction, origin + 6.0 * direction};
  std::vector<TimedPoint> points;
  for (int i = 0; i < 4; ++i) points.push_back({t[i], p[i]});
  const PointCurveMotion centripetal(PointCurve::neville_centripetal, points);
  const PointCurveMotion uniform(PointCurve::neville_uniform, points);
  const std::array<double, 4> u_centripetal{0.0, 1.0, 3.0, 4.0}, u_uniform{0.0, 1.0, 2.0, 3.0};
  double largest_gap = 0.0;
  for (const double x : between_times(points)) {
    const Point expected = lagrange_cubic(u_centripetal, p, four_point_parameter(t, u_centripetal, x));
    EXPECT_NEAR(std::abs(centripetal.at(x) - expected), 0.0, 1e-12) << x;
    // Still on the line (only the speed along it differs).
    EXPECT_NEAR(std::imag((centripetal.at(x) - origin) / direction), 0.0, 1e-12) << x;
    EXPECT_NEAR(std::abs(uniform.at(x) - lagrange_cubic(u_uniform, p, four_point_parameter(t, u_uniform, x))), 0.0,
                1e-12)
        << x;
    largest_gap = std::max(largest_gap, std::abs(centripetal.at(x) - uniform.at(x)));
  }
  EXPECT_GT(largest_gap, 0.1);  // the two parameterisations differ
}

// Equally spaced collinear points: equal centripetal steps, so the polynomial
// is linear in u, the straight line through them, at any knots.
TEST(PointCurveNevilleCentripetal, EquallySpacedCollinearPointsGiveTheLine) {
  const Point origin{-3.0, 0.5};
  const Vector step = std::polar(0.7, 2.2);
  Sampler s(5300);
  for (int n = 4; n <= 8; ++n) {
    const std::vector<double> knots = random_knots(s, n);
    std::vector<TimedPoint> points;
    for (int i = 0; i < n; ++i) points.push_back({knots[i], origin + static_cast<double>(i) * step});
    const PointCurveMotion curve(PointCurve::neville_centripetal, points);
    for (const double x : between_times(points)) {
      // Piecewise linear in t: the point on the polyline of the timed points.
      std::size_t i = 0;
      while (i + 2 < knots.size() && x > knots[i + 1]) ++i;
      const double index = static_cast<double>(i) + (x - knots[i]) / (knots[i + 1] - knots[i]);
      EXPECT_NEAR(std::abs(curve.at(x) - (origin + index * step)), 0.0, 1e-11) << "n=" << n << " t=" << x;
    }
  }
}

// ------------------------------------------------------------------ log-spiral blend

TEST(PointCurveLogSpiralBlend, PassesThroughEveryPointForFourToTenPoints) {
  Sampler s(5400);
  for (int n = 4; n <= 10; ++n) {
    for (int i = 0; i < 5; ++i) {
      const PointCurveMotion curve(PointCurve::log_spiral_blend, random_points(s, random_knots(s, n)));
      EXPECT_TRUE(passes_through_points(curve, 1e-9)) << "n=" << n << " #" << i;
    }
  }
}

// The four-point case written out: (1 - s) LS(a, b, c)(t) + s LS(b, c, d)(t),
// s = (t - t_0)/(t_3 - t_0).
TEST(PointCurveLogSpiralBlend, IsTheBlendOfTwoLogSpiralsForFourPoints) {
  Sampler s(5450);
  for (int i = 0; i < 10; ++i) {
    const std::vector<TimedPoint> p = random_points(s, random_knots(s, 4));
    const PointCurveMotion curve(PointCurve::log_spiral_blend, p);
    const LogSpiral first(p[0].p, p[1].p, p[2].p), second(p[1].p, p[2].p, p[3].p);
    for (const double t : between_times(p)) {
      const double w = (t - p[0].t) / (p[3].t - p[0].t);
      const Point expected = (1.0 - w) * first.at(lagrange_weights(p[0].t, p[1].t, p[2].t, t)) +
                             w * second.at(lagrange_weights(p[1].t, p[2].t, p[3].t, t));
      EXPECT_NEAR(std::abs(curve.at(t) - expected) / extent(p), 0.0, 1e-13) << "#" << i << " t=" << t;
    }
  }
}

// z_k = c + r e^{(alpha + i beta) k} at evenly spaced knots t_k = t_0 + h k:
// every three-point LS- is the spiral itself, so the curve is the spiral, at
// any t (extrapolation included).
TEST(PointCurveLogSpiralBlend, ReproducesALogSpiral) {
  const Point centre{0.5, -1.0};
  const Complex r = std::polar(1.5, 0.3);
  for (const Complex lambda : {Complex{0.15, 0.9}, Complex{-0.2, -1.3}, Complex{0.0, 2.5}}) {
    const auto spiral = [&](double k) { return centre + r * std::exp(lambda * k); };
    const double t0 = -0.4, h = 0.3;
    for (int n = 4; n <= 8; ++n) {
      std::vector<TimedPoint> points;
      for (int k = 0; k < n; ++k) points.push_back({t0 + h * k, spiral(k)});
      const PointCurveMotion curve(PointCurve::log_spiral_blend, points);
      const double e = extent(points);
      for (const double t : between_times(points)) {
        EXPECT_NEAR(std::abs(curve.at(t) - spiral((t - t0) / h)) / e, 0.0, 1e-11)
            << "lambda=" << lambda << " n=" << n << " t=" << t;
      }
    }
  }
}

// ------------------------------------------------------------------ invariance

// z -> scale e^{i angle} z + shift applied to the points moves the curve the
// same way (PITA Eq. 40 for points), for every rotation: the edges' windings follow
// the shape (each turns from the previous by the principal angle), so a
// rotation that takes an edge across the direction pi changes every winding
// by the same whole turn, which the similarity-invariant tracks P6 and P1
// carry through.
TEST(PointCurve, SimilarityInvariance) {
  struct Case {
    PointCurve curve;
    std::optional<Method> track;
  };
  const std::array<Case, 5> cases{{{PointCurve::pita, Method::P6},
                                   {PointCurve::pita, Method::P1},
                                   {PointCurve::neville_uniform, std::nullopt},
                                   {PointCurve::neville_centripetal, std::nullopt},
                                   {PointCurve::log_spiral_blend, std::nullopt}}};
  Sampler s(5500);
  for (const Case& c : cases) {
    const std::string label = std::string(info(c.curve).name) + (c.track ? " " + name(*c.track) : std::string());
    const ArrowTrackFactory track = c.track ? pita_track(*c.track) : ArrowTrackFactory{};
    for (int i = 0; i < 20; ++i) {
      const int n = c.track ? 4 : 4 + i % 5;
      const std::vector<TimedPoint> points =
          random_points(s, c.track                                   ? paper_knots()
                           : c.curve == PointCurve::log_spiral_blend ? nearly_even_knots(s, n)
                                                                     : random_knots(s, n));
      const double scale = std::exp(s.uniform(-2.0, 2.0));
      const double angle = s.uniform(-kPi, kPi);
      const Complex linear = std::polar(scale, angle);
      const Vector shift = s.point(10.0);
      std::vector<TimedPoint> moved;
      for (const TimedPoint& x : points) moved.push_back({x.t, linear * x.p + shift});
      const PointCurveMotion curve(c.curve, points, track), image(c.curve, moved, track);
      const double e = extent(moved);
      for (const double t : between_times(points)) {
        const Point expected = linear * curve.at(t) + shift;
        // Relative to the curve's own size there: the log-spiral blend grows
        // far from its knots (docs/paper-notes.md N34).
        EXPECT_NEAR(std::abs(image.at(t) - expected) / std::max(e, std::abs(expected - shift)), 0.0, 1e-9)
            << label << " #" << i << " t=" << t;
      }
    }
  }
}

// ------------------------------------------------------------------ bad input

// Expects std::invalid_argument whose message contains `part`.
::testing::AssertionResult refused(PointCurve curve, std::vector<TimedPoint> points, const std::string& part,
                                   const ArrowTrackFactory& track = pita_track(Method::P6)) {
  try {
    const PointCurveMotion motion(curve, std::move(points), track);
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).find(part) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "message \"" << e.what() << "\" lacks \"" << part << "\"";
  }
  return ::testing::AssertionFailure() << "accepted";
}

TEST(PointCurve, RefusesBadInput) {
  const std::vector<TimedPoint> good{{0.0, {0.0, 0.0}}, {1.0, {1.0, 0.0}}, {2.0, {1.0, 1.0}}, {3.0, {0.0, 2.0}}};
  for (const PointCurveInfo& c : all_point_curves()) {
    SCOPED_TRACE(std::string(c.name));
    EXPECT_NO_THROW(PointCurveMotion(c.curve, good, pita_track(Method::P6)));
    EXPECT_TRUE(refused(c.curve, {good.begin(), good.begin() + 3}, "at least 4 points, got 3"));
    EXPECT_TRUE(refused(c.curve, {}, "at least 4 points, got 0"));
    auto equal_knots = good;
    equal_knots[2].t = 1.0;
    EXPECT_TRUE(refused(c.curve, equal_knots, "strictly increasing (point 2"));
    auto decreasing = good;
    decreasing[3].t = -1.0;
    EXPECT_TRUE(refused(c.curve, decreasing, "strictly increasing (point 3"));
    auto nan_knot = good;
    nan_knot[1].t = std::nan("");
    EXPECT_TRUE(refused(c.curve, nan_knot, "point 1 must have a finite knot"));
    auto nan_point = good;
    nan_point[2].p = {1.0, std::nan("")};
    EXPECT_TRUE(refused(c.curve, nan_point, "point 2 must have a finite knot and finite coordinates"));
    auto infinite_point = good;
    infinite_point[0].p = {std::numeric_limits<double>::infinity(), 0.0};
    EXPECT_TRUE(refused(c.curve, infinite_point, "point 0 must have"));
  }
  auto coincident = good;
  coincident[2].p = coincident[1].p;
  EXPECT_TRUE(refused(PointCurve::pita, coincident, "point 1 and point 2 coincide"));
  EXPECT_TRUE(refused(PointCurve::neville_centripetal, coincident, "point 1 and point 2 coincide"));
  // The other curves take coincident consecutive points (LS- falls back to
  // the parabola there) and still pass through them.
  for (const PointCurve c : {PointCurve::neville_uniform, PointCurve::log_spiral_blend}) {
    const PointCurveMotion curve(c, coincident);
    EXPECT_TRUE(passes_through_points(curve, 1e-12));
  }
  EXPECT_TRUE(refused(PointCurve::pita, good, "needs an arrow track", ArrowTrackFactory{}));
}

TEST(PointCurve, NevilleTypeCurvesTakeAtMostTheLimit) {
  const int most = limits::kMaxNevillePoints;
  std::vector<TimedPoint> points;
  for (int i = 0; i <= most; ++i) points.push_back({static_cast<double>(i), std::polar(1.0 + i, 0.3 * i)});
  for (const PointCurve c :
       {PointCurve::neville_uniform, PointCurve::neville_centripetal, PointCurve::log_spiral_blend}) {
    EXPECT_TRUE(refused(c, points, "at most " + std::to_string(most) + " points")) << info(c).name;
    const PointCurveMotion curve(c, {points.begin(), points.end() - 1});
    EXPECT_TRUE(std::isfinite(std::abs(curve.at(0.5)))) << info(c).name;
  }
}

}  // namespace
}  // namespace pita::test
