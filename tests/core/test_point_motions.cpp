// The point motions of the PITAs (src/core/point_motions.cpp, Sec. 3.1): the
// parabolic Pa- (PITA Eq. 11) and the log-spiral LS- (PITA Eq. 26).
#include <cmath>
#include <complex>
#include <numbers>

#include "core/point_motions.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

// The quadratic Lagrange weights written out (PITA Eq. 10), so that the tests do
// not take them from the code they check.
LagrangeWeights weights(double a, double b, double c, double t) {
  return {(t - b) * (t - c) / ((a - b) * (a - c)), (t - a) * (t - c) / ((b - a) * (b - c)),
          (t - a) * (t - b) / ((c - a) * (c - b))};
}

// Points sampled from p(t) = p0 + v t + k t^2 are followed exactly, at any
// knots and any time, extrapolation included.
TEST(ParabolicPoint, FollowsTheParabolaThroughItsPoints) {
  const Point p0{1.0, -2.0}, v{3.0, 0.5}, k{-0.75, 1.25};
  const auto p = [&](double t) { return p0 + v * t + k * (t * t); };
  const double a = -0.5, b = 0.2, c = 1.5;
  for (const double t : {-1.0, -0.5, 0.0, 0.2, 0.9, 1.5, 3.0}) {
    const Point x = parabolic_point(weights(a, b, c, t), p(a), p(b), p(c));
    EXPECT_NEAR(std::abs(x - p(t)), 0.0, 1e-12) << t;
  }
}

TEST(LogSpiral, PassesThroughItsThreePointsAtTheKnots) {
  const Point pa{0.0, 0.0}, pb{2.0, 1.0}, pc{2.5, 3.5};
  const double a = 0.0, b = 0.3, c = 1.0;
  const LogSpiral spiral(pa, pb, pc);
  EXPECT_NEAR(std::abs(spiral.at(weights(a, b, c, a)) - pa), 0.0, 1e-14);
  EXPECT_NEAR(std::abs(spiral.at(weights(a, b, c, b)) - pb), 0.0, 1e-14);
  EXPECT_NEAR(std::abs(spiral.at(weights(a, b, c, c)) - pc), 0.0, 1e-14);
}

// Three points of one log spiral about f, r rho^u e^{i u theta} at u = 0, 1, 2:
// with even knots 0, 1, 2 the time map is u = t, and the motion is that spiral.
TEST(LogSpiral, FollowsTheSpiralThroughThreePointsOfIt) {
  const Point f{1.0, 2.0};
  const std::complex<double> r = std::polar(2.0, 0.3);
  const double rho = 1.5, theta = 1.1;
  const auto on_spiral = [&](double u) { return f + r * std::pow(rho, u) * std::polar(1.0, u * theta); };
  const LogSpiral spiral(on_spiral(0.0), on_spiral(1.0), on_spiral(2.0));
  for (const double t : {-0.5, 0.25, 0.5, 1.5, 2.5}) {
    EXPECT_NEAR(std::abs(spiral.at(weights(0.0, 1.0, 2.0, t)) - on_spiral(t)), 0.0, 1e-12) << t;
  }
  // Uneven knots 0, 0.3, 1: the same spiral, reached at u = y + 2z.
  const double t = 0.65;
  const double u = t * (1.0 - t) / (0.3 * 0.7) + 2.0 * t * (t - 0.3) / 0.7;
  EXPECT_NEAR(std::abs(spiral.at(weights(0.0, 0.3, 1.0, t)) - on_spiral(u)), 0.0, 1e-12);
}

// a = 0, b = 2, c = 1 on a line, b outside [a, c]: (c - b)/(b - a) = -1/2, so
// the twirl turns by the principal angle pi about f = 4/3 and the point leaves
// the line between the knots (the pop of LS-, Sec. 3.1): at u = 1/2 it is
// f + sqrt(1/2) e^{i pi/2} (a - f).
TEST(LogSpiral, CollinearPointsWithBOutsideTurnByPi) {
  const LogSpiral spiral({0.0, 0.0}, {2.0, 0.0}, {1.0, 0.0});
  const double t = 0.25;  // knots 0, 0.5, 1: u = y + 2z = 2t
  const Point x = spiral.at(weights(0.0, 0.5, 1.0, t));
  EXPECT_NEAR(x.real(), 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(x.imag(), -std::sqrt(0.5) * 4.0 / 3.0, 1e-14);
}

// b on a: no spiral through the points; the parabolic motion instead.
TEST(LogSpiral, CoincidentPointsFallBackToTheParabola) {
  const Point pa{1.0, 1.0}, pc{4.0, -1.0};
  for (const Point pb : {pa, pa + Point{1e-14, 0.0}}) {
    const LogSpiral spiral(pa, pb, pc);
    for (const double t : {0.25, 0.75, 1.5}) {
      const LagrangeWeights l = weights(0.0, 0.5, 1.0, t);
      const Point expected = l.x * pa + l.y * pb + l.z * pc;
      EXPECT_NEAR(std::abs(spiral.at(l) - expected), 0.0, 1e-13) << t;
      EXPECT_TRUE(std::isfinite(spiral.at(l).real()));
    }
  }
  EXPECT_NEAR(std::abs(log_spiral_point(weights(0.0, 0.5, 1.0, 1.0), pa, pa, pc) - pc), 0.0, 1e-15);
}

}  // namespace
}  // namespace pita::test
