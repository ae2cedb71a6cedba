// Time warps (src/core/time_warp.cpp): the ease over the knot range or per
// span, arc length, and the identity outside the knots (docs/paper-notes.md N20).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/time_warp.hpp"

namespace pita {
namespace {

TEST(TimeWarp, LinearWithoutArcLengthIsTheIdentity) {
  const TimeWarp warp(Ease{}, WarpSpan::motion, {0.0, 0.3, 2.0});
  EXPECT_TRUE(warp.is_identity());
  for (double t : {-1.0, 0.0, 0.17, 0.3, 1.9, 2.0, 5.0}) EXPECT_EQ(warp(t), t);
  EXPECT_TRUE(TimeWarp().is_identity());
}

TEST(TimeWarp, EaseOverTheWholeRange) {
  const Ease sine = *find_named_ease("sine");
  const TimeWarp warp(sine, WarpSpan::motion, {1.0, 1.5, 3.0});
  for (double t : {1.2, 1.5, 2.2, 2.9}) EXPECT_DOUBLE_EQ(warp(t), 1.0 + 2.0 * ease(sine, (t - 1.0) / 2.0)) << t;
  EXPECT_EQ(warp(1.0), 1.0);
  EXPECT_EQ(warp(3.0), 3.0);
  // Outside the knots: unchanged (extrapolation is not warped).
  EXPECT_EQ(warp(0.5), 0.5);
  EXPECT_EQ(warp(3.5), 3.5);
  EXPECT_NE(warp(1.5), 1.5);  // the middle knot is not reached at its time
}

TEST(TimeWarp, PerSpanReachesEveryKnotAtItsTime) {
  const Ease in = *find_named_ease("ease-in");
  const TimeWarp warp(in, WarpSpan::span, {0.0, 0.2, 1.0});
  for (double t : {0.0, 0.2, 1.0}) EXPECT_EQ(warp(t), t);
  EXPECT_DOUBLE_EQ(warp(0.1), 0.2 * ease(in, 0.5));
  EXPECT_DOUBLE_EQ(warp(0.6), 0.2 + 0.8 * ease(in, 0.5));
}

TEST(TimeWarp, ArcLengthGivesEqualDistancesAtEqualTimes) {
  // A point accelerating along a line: x = tau^2.
  const ArcLengthTable::Path path = [](double tau) { return Point{tau * tau, 0.0}; };
  const TimeWarp warp(Ease{}, WarpSpan::motion, {0.0, 0.5, 1.0}, &path);
  ASSERT_NE(warp.table(0), nullptr);
  for (int i = 0; i <= 20; ++i) {
    const double t = i / 20.0;
    EXPECT_NEAR(path(warp(t)).real(), t, 1e-12) << t;
  }
}

TEST(TimeWarp, ArcLengthAfterTheEaseFollowsTheEase) {
  // p = P(U(S(t))) (the chapter's Sec. 3.2.2): the distance covered is ease(t).
  const ArcLengthTable::Path path = [](double tau) { return Point{std::sin(tau), std::cos(3 * tau)}; };
  const Ease e = *find_named_ease("ease-in-out");
  const TimeWarp warp(e, WarpSpan::motion, {0.0, 2.0}, &path);
  const ArcLengthTable& table = *warp.table(0);
  for (int i = 0; i <= 20; ++i) {
    const double t = 2.0 * i / 20.0;
    EXPECT_NEAR(table.length_at(warp(t)) / table.length(), ease(e, t / 2.0), 1e-10) << t;
  }
}

TEST(TimeWarp, ArcLengthPerSpanIsUniformWithinEachSpan) {
  const ArcLengthTable::Path path = [](double tau) { return Point{std::exp(tau), 0.0}; };
  const TimeWarp warp(Ease{}, WarpSpan::span, {0.0, 1.0, 3.0}, &path);
  EXPECT_EQ(warp(1.0), 1.0);
  EXPECT_NEAR(path(warp(0.5)).real(), 0.5 * (1.0 + std::exp(1.0)), 1e-11);
  EXPECT_NEAR(path(warp(2.0)).real(), 0.5 * (std::exp(1.0) + std::exp(3.0)), 1e-9);
}

TEST(TimeWarp, ArcLengthOfAStillSpanIsRefused) {
  const ArcLengthTable::Path path = [](double tau) { return Point{std::min(tau, 1.0), 0.0}; };
  EXPECT_NO_THROW(TimeWarp(Ease{}, WarpSpan::motion, {0.0, 1.0, 2.0}, &path));
  EXPECT_THROW(TimeWarp(Ease{}, WarpSpan::span, {0.0, 1.0, 2.0}, &path), std::invalid_argument);
}

TEST(TimeWarp, OvershootExtrapolatesWithoutArcLengthAndClampsWithIt) {
  const Ease back = cubic_bezier_ease(0.2, 1.5, 0.8, 1.5);  // y above 1 in the middle
  const TimeWarp warp(back, WarpSpan::motion, {0.0, 2.0});
  EXPECT_GT(ease(back, 0.6), 1.0);
  EXPECT_DOUBLE_EQ(warp(1.2), 2.0 * ease(back, 0.6));  // beyond the last knot
  const ArcLengthTable::Path path = [](double tau) { return Point{tau, 0.0}; };
  const TimeWarp paced(back, WarpSpan::motion, {0.0, 2.0}, &path);
  EXPECT_EQ(paced(1.2), 2.0);
  const Ease under = cubic_bezier_ease(0.3, -0.8, 0.7, 0.5);
  EXPECT_LT(ease(under, 0.25), 0.0);
  EXPECT_LT(TimeWarp(under, WarpSpan::motion, {0.0, 2.0})(0.5), 0.0);
  EXPECT_EQ(TimeWarp(under, WarpSpan::motion, {0.0, 2.0}, &path)(0.5), 0.0);
}

TEST(TimeWarp, KnotsMustIncrease) {
  EXPECT_THROW(TimeWarp(Ease{}, WarpSpan::motion, {0.0}), std::invalid_argument);
  EXPECT_THROW(TimeWarp(Ease{}, WarpSpan::motion, {0.0, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace pita
