// The grazing point of a moving edge (core/grazing_point.hpp, SAM paper
// Sec. 7.2, SAM Eq. 8): its velocity is parallel to the edge (checked with a
// finite difference of the motion, not its velocity), it is the foot of the
// perpendicular from the centre of a rotation, it stays the same point of
// the edge under a SAM (SAM Eq. 8) and moves along the edge under rARAP.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/affine_power.hpp"
#include "core/grazing_point.hpp"
#include "core/pose_motion.hpp"
#include "pose_test_support.hpp"

namespace pita {
namespace {

using pita::test::affinity;

// The rotation by `angle` about `centre`, scaled by `scale`.
Affine2 spiral_about(const Eigen::Vector2d& centre, double angle, double scale) {
  Affine2 A;
  A.L << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  A.L *= scale;
  A.b = centre - A.L * centre;
  return A;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// An affine first pose and a rotation with shear and scaling, as in Fig. 10.
const Affine2 kFirst = affinity(1.2, 0.3, 0.5, -0.1, 0.9, -0.2);
const Affine2 kLast = affinity(-0.4, -1.3, 3.0, 1.0, -0.2, 2.5);
const Edge kEdge{Eigen::Vector2d(-1.0, 0.4), Eigen::Vector2d(1.5, 0.9)};

// The velocity of the edge's point x(s) at t by a fourth-order central
// difference of the poses alone.
Eigen::Vector2d finite_velocity(const PoseMotion& motion, const Edge& edge, double s, double t) {
  const Eigen::Vector2d x = edge.from + s * (edge.to - edge.from);
  const double h = 1e-3;
  const auto at = [&](double u) { return apply(motion.at(u), x); };
  return (at(t - 2 * h) - 8.0 * at(t - h) + 8.0 * at(t + h) - at(t + 2 * h)) / (12.0 * h);
}

// sin of the angle between the point's velocity and the edge at time t.
double sine_to_edge(const PoseMotion& motion, const Edge& edge, double s, double t) {
  const Eigen::Vector2d direction = motion.at(t).L * (edge.to - edge.from);
  const Eigen::Vector2d v = finite_velocity(motion, edge, s, t);
  return cross(direction, v) / (direction.norm() * v.norm());
}

TEST(GrazingPoint, VelocityParallelToTheEdgeByFiniteDifferences) {
  for (const PoseMethod method : {PoseMethod::sam, PoseMethod::rarap, PoseMethod::linear}) {
    const PoseMotion motion(method, {{0.0, kFirst}, {1.0, kLast}});
    for (const double t : {0.05, 0.3, 0.5, 0.77, 0.95}) {
      SCOPED_TRACE(::testing::Message() << info(method).id << " t = " << t);
      const std::optional<double> s = grazing_parameter(motion.at(t), motion.velocity(t), kEdge);
      ASSERT_TRUE(s.has_value());
      EXPECT_LT(std::abs(sine_to_edge(motion, kEdge, *s, t)), 1e-9);
      // Another point of the edge does not graze: the check can fail.
      EXPECT_GT(std::abs(sine_to_edge(motion, kEdge, *s + 0.25, t)), 1e-3);
    }
  }
}

// A rotation about c: every point moves on a circle about c, so the point of
// the edge's line whose velocity is along the line is the foot of the
// perpendicular from c, at every time.
TEST(GrazingPoint, RotationGrazesAtTheFootOfThePerpendicular) {
  const Eigen::Vector2d c(0.7, -1.9);
  const PoseMotion motion(PoseMethod::sam, {{0.0, Affine2::identity()}, {1.0, spiral_about(c, 2.0, 1.0)}});
  const Eigen::Vector2d d = kEdge.to - kEdge.from;
  const double foot = (c - kEdge.from).dot(d) / d.squaredNorm();
  for (const double t : {0.0, 0.4, 1.0}) {
    const std::optional<double> s = grazing_parameter(motion.at(t), motion.velocity(t), kEdge);
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(*s, foot, 1e-13);
  }
}

// SAM Eq. 8: under a SAM the grazing parameter is the same at every time, and
// equals the closed form from log A and the first pose.
TEST(GrazingPoint, SamGrazesAtOneFixedPointOfTheEdge) {
  const PoseMotion motion(PoseMethod::sam, {{0.0, kFirst}, {1.0, kLast}});
  const Affine2 generator = log(compose(kLast, inverse(kFirst)));
  const std::optional<double> eq8 = sam_grazing_parameter(generator, kFirst, kEdge);
  ASSERT_TRUE(eq8.has_value());
  EXPECT_GT(*eq8, 0.0);  // on the edge: the configuration means something
  EXPECT_LT(*eq8, 1.0);
  for (int i = 0; i <= 100; ++i) {
    const double t = -0.5 + 2.0 * i / 100.0;  // extrapolated too
    const std::optional<double> s = grazing_parameter(motion.at(t), motion.velocity(t), kEdge);
    ASSERT_TRUE(s.has_value());
    EXPECT_NEAR(*s, *eq8, 1e-12) << "t = " << t;
  }
}

// rARAP between the same poses moves the grazing point along the edge.
TEST(GrazingPoint, RarapGrazingPointMovesAlongTheEdge) {
  const PoseMotion motion(PoseMethod::rarap, {{0.0, kFirst}, {1.0, kLast}});
  double low = 1e300, high = -1e300;
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;
    const std::optional<double> s = grazing_parameter(motion.at(t), motion.velocity(t), kEdge);
    ASSERT_TRUE(s.has_value());
    low = std::min(low, *s);
    high = std::max(high, *s);
  }
  EXPECT_GT(high - low, 0.05);
}

// An edge that does not turn has no single grazing point: a translation
// (every point moves along or across the whole line), a stretch along the
// edge; a turn so slow that the point is a million edge lengths away.
TEST(GrazingPoint, NoneWhenTheEdgeDoesNotTurn) {
  const Affine2 translation = affinity(0.0, 0.0, 1.0, 0.0, 0.0, 2.0);  // as a velocity
  EXPECT_FALSE(grazing_parameter(Affine2::identity(), translation, kEdge).has_value());
  const Edge horizontal{Eigen::Vector2d(0.0, 1.0), Eigen::Vector2d(2.0, 1.0)};
  const Affine2 stretch = affinity(0.5, 0.0, 0.0, 0.0, 0.0, 0.3);  // x grows, y moves
  EXPECT_FALSE(grazing_parameter(Affine2::identity(), stretch, horizontal).has_value());
  EXPECT_FALSE(sam_grazing_parameter(stretch, Affine2::identity(), horizontal).has_value());
  // The field x -> w J x + (0, 1) on the edge (2s, 1): velocity (-w, 2ws + 1),
  // along the edge when s = -1/(2w); beyond a million edge lengths, none.
  const auto turning = [](double w) { return affinity(0.0, -w, 0.0, w, 0.0, 1.0); };
  EXPECT_NEAR(*grazing_parameter(Affine2::identity(), turning(0.25), horizontal), -2.0, 1e-12);
  EXPECT_NEAR(*grazing_parameter(Affine2::identity(), turning(1e-6), horizontal), -5e5, 1e-6);
  EXPECT_FALSE(grazing_parameter(Affine2::identity(), turning(1e-7), horizontal).has_value());
}

}  // namespace
}  // namespace pita
