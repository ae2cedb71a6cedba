// Arc length and its inverse (src/core/arc_length.cpp) against closed forms:
// circles, a log-spiral, a parabola, a path clamped outside its interval, and
// the refusal of a still point (docs/paper-notes.md N20).
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/arc_length.hpp"

namespace pita {
namespace {

TEST(ArcLength, CircleLengthAndInverseAreExact) {
  const double r = 2.5;
  const ArcLengthTable table([&](double t) { return std::polar(r, t) + Point{10, -3}; }, 0.0, 2 * kPi);
  EXPECT_NEAR(table.length(), 2 * kPi * r, 1e-11 * table.length());
  for (int i = 0; i <= 50; ++i) {
    const double f = i / 50.0;
    EXPECT_NEAR(table.parameter_at(f), 2 * kPi * f, 1e-10) << f;
    EXPECT_NEAR(table.length_at(2 * kPi * f), 2 * kPi * r * f, 1e-10) << f;
  }
  EXPECT_EQ(table.parameter_at(0.0), 0.0);
  EXPECT_EQ(table.parameter_at(1.0), 2 * kPi);
}

TEST(ArcLength, LogSpiralOfManyTurnsMatchesItsClosedForm) {
  // z(t) = e^{(a + i) t}: |z'| = sqrt(1 + a^2) e^{a t}, s(t) = sqrt(1 + a^2)(e^{a t} - 1)/a.
  const double a = 0.15, T = 30.0;  // almost five turns, radius from 1 to 90
  const ArcLengthTable table([&](double t) { return std::exp(Complex{a, 1.0} * t); }, 0.0, T);
  const auto s = [&](double t) { return std::sqrt(1 + a * a) * std::expm1(a * t) / a; };
  EXPECT_NEAR(table.length(), s(T), 1e-9 * s(T));
  for (int i = 1; i < 40; ++i) {
    const double f = i / 40.0;
    const double t = std::log1p(f * s(T) * a / std::sqrt(1 + a * a)) / a;  // the exact inverse
    EXPECT_NEAR(s(table.parameter_at(f)), f * s(T), 1e-9 * s(T)) << f;
    EXPECT_NEAR(table.parameter_at(f), t, 1e-9 * T) << f;
  }
}

TEST(ArcLength, HelixInSpaceMatchesItsClosedForm) {
  // (r cos t, r sin t, c t): speed sqrt(r^2 + c^2), constant.
  const double r = 1.5, c = 0.4, T = 4 * kPi;
  const ArcLengthTable::Path3 helix = [&](double t) {
    return Eigen::Vector3d(r * std::cos(t), r * std::sin(t), c * t);
  };
  const ArcLengthTable table(helix, 0.0, T);
  const double speed = std::sqrt(r * r + c * c);
  EXPECT_NEAR(table.length(), speed * T, 1e-11 * speed * T);
  for (int i = 0; i <= 20; ++i) EXPECT_NEAR(table.parameter_at(i / 20.0), T * i / 20.0, 1e-10) << i;
}

TEST(ArcLength, PathOfThePlaneInSpaceHasItsPlaneLength) {
  const auto s = [](double x) { return (x * std::sqrt(1 + 4 * x * x)) / 2 + std::asinh(2 * x) / 4; };
  const ArcLengthTable::Path3 lifted = [](double x) { return Eigen::Vector3d(x, x * x, 5.0); };
  const ArcLengthTable table(lifted, -1.0, 2.0);
  EXPECT_NEAR(table.length(), s(2.0) - s(-1.0), 1e-11 * (s(2.0) - s(-1.0)));
  const ArcLengthTable::Path3 still = [](double) { return Eigen::Vector3d(1.0, 2.0, 3.0); };
  EXPECT_THROW(ArcLengthTable(still, 0.0, 1.0), std::invalid_argument);
}

TEST(ArcLength, ParabolaMatchesItsClosedForm) {
  const auto s = [](double x) { return (x * std::sqrt(1 + 4 * x * x)) / 2 + std::asinh(2 * x) / 4; };
  const ArcLengthTable table([](double x) { return Point{x, x * x}; }, -1.0, 2.0);
  const double total = s(2.0) - s(-1.0);
  EXPECT_NEAR(table.length(), total, 1e-11 * total);
  for (double x : {-0.7, 0.0, 0.3, 1.9}) EXPECT_NEAR(table.length_at(x), s(x) - s(-1.0), 1e-10 * total) << x;
}

TEST(ArcLength, PathClampedOutsideItsIntervalIsMeasuredInside) {
  // Like the Bezier SAM, which holds its end poses outside its knots.
  const auto clamped = [](double t) {
    const double u = std::clamp(t, 0.0, 1.0);
    return Point{u, 0.0};
  };
  const ArcLengthTable table(clamped, 0.0, 1.0);
  EXPECT_NEAR(table.length(), 1.0, 1e-12);
  EXPECT_NEAR(table.parameter_at(0.3), 0.3, 1e-12);
}

TEST(ArcLength, PointThatStopsMidwayIsInvertedMonotonically) {
  // x = t^3 stops at t = 0: speed 3t^2 vanishes there.
  const ArcLengthTable table([](double t) { return Point{t * t * t, 0.0}; }, -1.0, 1.0);
  EXPECT_NEAR(table.length(), 2.0, 1e-10);
  double previous = -1.0;
  for (int i = 1; i < 100; ++i) {
    const double t = table.parameter_at(i / 100.0);
    EXPECT_GT(t, previous);
    EXPECT_NEAR(t * t * t, -1.0 + 2.0 * i / 100.0, 1e-9);
    previous = t;
  }
}

TEST(ArcLength, StillPointHasNoLength) {
  EXPECT_THROW(ArcLengthTable([](double) { return Point{3.0, 4.0}; }, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ArcLengthTable([](double t) { return Point{t, 0.0}; }, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ArcLengthTable([](double t) { return Point{t / 0.0, 0.0}; }, 0.0, 1.0), std::invalid_argument);
}

TEST(ArcLength, TinyAndHugeScalesAreMeasuredRelatively) {
  for (const double scale : {1e-30, 1e30}) {
    const ArcLengthTable table([&](double t) { return scale * std::polar(1.0, t); }, 0.0, kPi);
    EXPECT_NEAR(table.length() / scale, kPi, 1e-11) << scale;
  }
}

// Issue 37: a short path far from the origin whose points carry rounding
// noise (as a motion's do: logs, exponentials, sines) cannot meet a tolerance
// relative to its own small length. The table stops refining at the noise
// floor of limits.hpp instead of halving every interval to the maximum depth:
// a per-span warp of a 1000-keyframe track took minutes. The length stays
// right to far better than the noise.
TEST(ArcLength, NoisyShortPathFarAwayStopsRefiningAtTheRounding) {
  const auto noise = [](double t) {  // deterministic, in [-1, 1]
    std::uint64_t x = std::bit_cast<std::uint64_t>(t) * 0x9E3779B97F4A7C15ull;
    x ^= x >> 29;
    return static_cast<double>(x % 2001) / 1000.0 - 1.0;
  };
  const double r = 0.01, far = 1000.0;
  const ArcLengthTable table(
      [&](double t) {
        const Point p = Point{far, far} + std::polar(r, t);
        return p + 4e-16 * far * Point{noise(t), noise(t + 1.0)};
      },
      0.0, 1.0);
  EXPECT_LE(table.intervals(), 256u);  // 16 x 2^8 = 4096 when refined to the end
  EXPECT_NEAR(table.length(), r, 1e-6 * r);
}

}  // namespace
}  // namespace pita
