// The region swept by a moving edge (analysis/swept_edge.hpp, SAM paper
// Fig. 10): the envelope is where each copy of the edge touches it (the limit
// of the intersections of neighbouring copies, computed here from the poses
// alone), every copy lies on one side of it, it ends where the grazing point
// leaves the edge, and the grazing parameter is constant under a SAM only.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../core/pose_test_support.hpp"
#include "analysis/swept_edge.hpp"
#include "core/affine_power.hpp"
#include "core/pose_motion.hpp"

namespace pita::analysis {
namespace {

using pita::test::affinity;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The poses and edge of scenes/sam-fig10-swept-edge.json: the identity, then
// a turn by about 140 degrees with a shrink and a shear; rARAP moves the
// barycentre of the reference triangle, the edge's midpoint (0.9, 1.2).
const Affine2 kFirst = Affine2::identity();
const Affine2 kLast = affinity(-0.6, -0.5, 3.0, 0.45, -0.5, 3.0);
const Edge kEdge{Eigen::Vector2d(-0.6, 1.2), Eigen::Vector2d(2.4, 1.2)};
const std::array<Point, 3> kReference{Point(-0.6, 0.9), Point(2.4, 0.9), Point(0.9, 1.8)};

PoseMotion motion_of(PoseMethod method) { return PoseMotion(method, {{0.0, kFirst}, {1.0, kLast}}, 4, kReference); }

PoseTrack track_of(const PoseMotion& motion) {
  return {[&motion](double t) { return motion.at(t); }, [&motion](double t) { return motion.velocity(t); }};
}

// The characteristic point at t: where the copies of the edge's line at t - h
// and t + h meet (the envelope of a family of lines, by finite differences),
// as the parameter s along the edge at t. Poses only.
double characteristic_parameter(const PoseMotion& motion, const Edge& edge, double t) {
  const double h = 1e-5;
  const Affine2 P = motion.at(t - h), Q = motion.at(t + h);
  const Eigen::Vector2d p = apply(P, edge.from), dp = P.L * (edge.to - edge.from);
  const Eigen::Vector2d q = apply(Q, edge.from), dq = Q.L * (edge.to - edge.from);
  const double lambda = cross(q - p, dq) / cross(dp, dq);  // p + lambda dp on the line at t + h
  const Eigen::Vector2d meet = p + lambda * dp;
  const Affine2 A = motion.at(t);
  const Eigen::Vector2d d = A.L * (edge.to - edge.from);
  return (meet - apply(A, edge.from)).dot(d) / d.squaredNorm();
}

TEST(SweptEdge, GrazingPointIsTheCharacteristicPoint) {
  for (const PoseMethod method : {PoseMethod::sam, PoseMethod::rarap}) {
    const PoseMotion motion = motion_of(method);
    const GrazingTrace trace = trace_grazing(track_of(motion), kEdge, 0.0, 1.0, 41);
    ASSERT_EQ(trace.times.size(), 41u);
    for (std::size_t i = 1; i + 1 < trace.times.size(); ++i) {
      SCOPED_TRACE(::testing::Message() << info(method).id << " t = " << trace.times[i]);
      ASSERT_TRUE(trace.s[i].has_value());
      EXPECT_NEAR(*trace.s[i], characteristic_parameter(motion, kEdge, trace.times[i]), 1e-6);
    }
  }
}

// The claim of Fig. 10: constant under the SAM (and equal to SAM Eq. 8), not
// under rARAP, whose range is recomputed here from characteristic points.
TEST(SweptEdge, GrazingRangeConstantForSamOnly) {
  const PoseMotion sam = motion_of(PoseMethod::sam);
  const GrazingRange steady = grazing_range(trace_grazing(track_of(sam), kEdge, 0.0, 1.0, 257));
  EXPECT_EQ(steady.defined, 257);
  EXPECT_LE(steady.spread(), kConstantGrazingSpread);
  const std::optional<double> eq8 = sam_grazing_parameter(log(compose(kLast, inverse(kFirst))), kFirst, kEdge);
  ASSERT_TRUE(eq8.has_value());
  EXPECT_NEAR(steady.min, *eq8, 1e-12);

  const PoseMotion rarap = motion_of(PoseMethod::rarap);
  const GrazingTrace trace = trace_grazing(track_of(rarap), kEdge, 0.0, 1.0, 257);
  const GrazingRange moving = grazing_range(trace);
  double low = 1e300, high = -1e300;
  for (const double t : trace.times) {
    const double s = characteristic_parameter(rarap, kEdge, std::clamp(t, 1e-4, 1.0 - 1e-4));
    low = std::min(low, s);
    high = std::max(high, s);
  }
  EXPECT_NEAR(moving.min, low, 1e-3);
  EXPECT_NEAR(moving.max, high, 1e-3);
  EXPECT_GT(moving.spread(), 0.1);
}

// Each copy of the edge touches the envelope (the envelope point of its time
// lies on it) and the whole envelope lies on one side of its line.
TEST(SweptEdge, CopiesTouchTheEnvelopeFromOneSide) {
  for (const PoseMethod method : {PoseMethod::sam, PoseMethod::rarap}) {
    SCOPED_TRACE(info(method).id);
    const PoseMotion motion = motion_of(method);
    const GrazingTrace trace = trace_grazing(track_of(motion), kEdge, 0.0, 1.0, 401);
    const auto runs = envelope(track_of(motion), kEdge, trace);
    ASSERT_FALSE(runs.empty());
    std::vector<Eigen::Vector2d> points;
    for (const auto& run : runs) points.insert(points.end(), run.begin(), run.end());
    int touched = 0;
    for (std::size_t i = 0; i < trace.times.size(); i += 10) {
      const Affine2 A = motion.at(trace.times[i]);
      const Eigen::Vector2d p = apply(A, kEdge.from), d = A.L * (kEdge.to - kEdge.from);
      double nearest = 1e300, low = 1e300, high = -1e300;
      for (const Eigen::Vector2d& e : points) {
        const double side = cross(d, e - p) / d.norm();  // signed distance to the line
        low = std::min(low, side);
        high = std::max(high, side);
        const double along = std::clamp((e - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
        nearest = std::min(nearest, (p + along * d - e).norm());
      }
      // One side: the smaller of the two extents is rounding.
      EXPECT_LT(std::min(-low, high), 1e-12) << "t = " << trace.times[i];
      if (trace.s[i] && *trace.s[i] >= 0.0 && *trace.s[i] <= 1.0) {
        EXPECT_LT(nearest, 1e-12) << "t = " << trace.times[i];
        ++touched;
      }
    }
    EXPECT_GT(touched, 10);
  }
}

// Under rARAP the grazing point leaves a shorter edge: the envelope ends at
// the edge's end, on the path of that end.
TEST(SweptEdge, EnvelopeEndsWhereTheGrazingPointLeavesTheEdge) {
  const PoseMotion motion = motion_of(PoseMethod::rarap);
  // The left two thirds of the edge: s' = 1.5 s runs from about 0.45 to 1.2.
  const Edge shorter{Eigen::Vector2d(-0.6, 1.2), Eigen::Vector2d(1.4, 1.2)};
  const GrazingTrace trace = trace_grazing(track_of(motion), shorter, 0.0, 1.0, 65);
  const auto runs = envelope(track_of(motion), shorter, trace);
  ASSERT_FALSE(runs.empty());
  // The ends of the edge, densely.
  const GrazingTrace dense = trace_grazing(track_of(motion), shorter, 0.0, 1.0, 20001);
  int checked = 0;
  for (const auto& run : runs) {
    for (const Eigen::Vector2d& end : {run.front(), run.back()}) {
      double nearest = 1e300;
      for (const double t : dense.times) {
        const Affine2 A = motion.at(t);
        nearest = std::min({nearest, (apply(A, shorter.from) - end).norm(), (apply(A, shorter.to) - end).norm()});
      }
      // An end of a run is the envelope at t = 0 or 1, or an end of the edge.
      const Affine2 A0 = motion.at(0.0), A1 = motion.at(1.0);
      const double s0 = *trace.s.front(), s1 = *trace.s.back();
      const double at_knots = std::min((apply(A0, shorter.from + s0 * (shorter.to - shorter.from)) - end).norm(),
                                       (apply(A1, shorter.from + s1 * (shorter.to - shorter.from)) - end).norm());
      if (at_knots < 1e-12) continue;
      EXPECT_LT(nearest, 1e-3);
      ++checked;
    }
  }
  EXPECT_GE(checked, 1);  // the configuration leaves the edge at least once
}

// A pole of s (the denominator of SAM Eq. 8 changes sign) between a sample on
// the edge and one off it: the run must end where s passes 1 before the
// pole, not at the pole or at the last sample. The edge stays put (pose I)
// while its line is turned by L'(t) = [[0, 0], [t - 1/2, 0]] and pushed by
// c' = (0, -0.2): s(t) = 0.2 / (t - 1/2), so s = 1 at t = 0.7 exactly.
TEST(SweptEdge, EnvelopeEndIsFoundPastAPoleOfTheGrazingParameter) {
  const PoseTrack track{[](double) { return Affine2::identity(); },
                        [](double t) { return affinity(0.0, 0.0, 0.0, t - 0.5, 0.0, -0.2); }};
  const Edge edge{Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.0, 0.0)};
  GrazingTrace trace;
  for (const double t : {0.3, 0.75, 1.0}) {
    trace.times.push_back(t);
    trace.s.push_back(grazing_parameter(track.pose(t), track.velocity(t), edge));
  }
  ASSERT_TRUE(trace.s[0].has_value());
  EXPECT_NEAR(*trace.s[0], -1.0, 1e-15);  // off the edge, beyond the pole at t = 1/2
  EXPECT_NEAR(*trace.s[1], 0.8, 1e-15);
  const auto runs = envelope(track, edge, trace);
  ASSERT_EQ(runs.size(), 1u);
  ASSERT_EQ(runs[0].size(), 3u);
  EXPECT_LT((runs[0].front() - Eigen::Vector2d(1.0, 0.0)).norm(), 1e-12);  // s = 1 at t = 0.7
  EXPECT_LT((runs[0].back() - Eigen::Vector2d(0.4, 0.0)).norm(), 1e-15);   // s(1) = 0.4, the last sample
}

}  // namespace
}  // namespace pita::analysis
