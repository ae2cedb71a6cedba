// The motions of pose scenes (src/core/pose_motion.cpp): SAM, polySAM,
// Bezier SAM, bi-arc, linear and four-point, through timed poses.
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/pose_motion.hpp"
#include "core/sam_splines.hpp"
#include "pose_test_support.hpp"

namespace pita {
namespace {

using test::distance;
using test::pose;

const Affine2& kA = test::kFig7A;
const Affine2& kB = test::kFig7B;
const Affine2& kC = test::kFig7C;

TEST(PoseMotion, PolySamInterpolatesEveryPose) {
  const PoseMotion motion(PoseMethod::poly_sam, {{0.0, kA}, {0.4, kB}, {1.0, kC}});
  EXPECT_LT(distance(motion.at(0.0), kA), 1e-15);
  EXPECT_LT(distance(motion.at(0.4), kB), 1e-15);
  EXPECT_LT(distance(motion.at(1.0), kC), 1e-15);
  EXPECT_LT(distance(motion.at(0.2), sam(kA, 0.5, kB)), 1e-14);
  EXPECT_LT(distance(motion.at(0.7), sam(kB, 0.5, kC)), 1e-14);
}

// PoseMotion::velocity against central differences of PoseMotion::at.
TEST(PoseMotion, VelocityIsTheDerivative) {
  const std::vector<TimedPose> poses = {{0.0, kA}, {0.4, kB}, {1.0, kC}};
  for (const PoseMethod method :
       {PoseMethod::poly_sam, PoseMethod::linear, PoseMethod::bezier_sam, PoseMethod::biarc_sam}) {
    const PoseMotion motion(method, poses);
    for (const double t : {0.1, 0.3, 0.55, 0.9}) {
      const double h = 1e-6;
      const Affine2 before = motion.at(t - h), after = motion.at(t + h);
      const Affine2 expected{(after.L - before.L) / (2.0 * h), (after.b - before.b) / (2.0 * h)};
      EXPECT_LT(distance(motion.velocity(t), expected), 1e-6 * (1.0 + expected.L.norm() + expected.b.norm()))
          << info(method).id << " at t = " << t;
    }
  }
  const PoseMotion sam(PoseMethod::sam, {{0.0, kA}, {2.0, kB}});
  EXPECT_LT(distance(sam.at(0.0), kA), 1e-15);
  EXPECT_LT(distance(sam.at(2.0), kB), 1e-15);
  const PoseMotion biarc(PoseMethod::biarc_sam, poses);
  EXPECT_LT(distance(biarc.at(0.4), kB), 1e-15);  // through the middle pose at its knot
}

TEST(PoseMotion, RefusesTheMissingSamAndNamesThePair) {
  try {
    PoseMotion motion(PoseMethod::poly_sam, {{0.0, kB}, {0.5, kA}, {1.0, kC}});
    FAIL() << "no SAM from A to C expected";
  } catch (const NoSamBetweenPoses& error) {
    EXPECT_EQ(error.first(), 1u);
  }
}

// The four-point polySAM (Sec. 7.3, Fig. 13).
TEST(PoseMotion, FourPointPolySam) {
  const std::vector<TimedPose> controls = {{0.0, pose(1.0, 0.0, 0.0, 1.0, 0.0, 0.0)},
                                           {1.0, pose(0.4, -1.2, 1.2, 0.4, 3.0, 4.0)},
                                           {2.0, pose(-1.2, -0.6, 0.5, -1.1, 7.0, 3.5)},
                                           {3.0, pose(-0.9, 0.5, -0.3, -1.0, 9.0, -1.0)}};
  // Through every control pose, whatever the number of steps.
  for (const int steps : {0, 1, 2, 4}) {
    const PoseMotion motion(PoseMethod::four_point, controls, steps);
    for (const TimedPose& control : controls) {
      EXPECT_LT(distance(motion.at(control.t), control.pose), 1e-12) << steps << " at " << control.t;
    }
  }
  // No step: the polySAM.
  const PoseMotion none(PoseMethod::four_point, controls, 0);
  const PoseMotion poly(PoseMethod::poly_sam, controls);
  for (const double t : {0.3, 1.5, 2.7}) EXPECT_LT(distance(none.at(t), poly.at(t)), 1e-15);
  // Each step shrinks the velocity jump at the control poses.
  const auto jump = [&](int steps) {
    const PoseMotion motion(PoseMethod::four_point, controls, steps);
    const Affine2 before = motion.velocity(1.0 - 1e-9), after = motion.velocity(1.0);
    return distance(before, after);
  };
  // (measured: 10.1, 6.1, 3.6, 2.1, 1.2, 0.68: about 1.75 times smaller per step,
  // towards a C1 limit)
  for (int k = 0; k < 5; ++k) EXPECT_LT(jump(k + 1), jump(k) / 1.5) << k;
  // A regular pattern stays one SAM: controls M^i B give M^t B at every t.
  const Affine2 M = pose(0.9, -0.3, 0.3, 0.9, 1.0, 0.5), B = pose(1.0, 0.2, 0.0, 1.0, 0.0, 0.0);
  const AffinePowers powers(M);
  std::vector<TimedPose> regular;
  for (int i = 0; i < 4; ++i) regular.push_back({static_cast<double>(i), compose(powers.at(i), B)});
  const PoseMotion smooth(PoseMethod::four_point, regular, 3);
  for (const double t : {0.1, 0.75, 1.5, 2.9}) {
    EXPECT_LT(distance(smooth.at(t), compose(powers.at(t), B)), 1e-11) << t;
  }
}

// Linear: every entry moves at constant speed, (1 - u) A + u B with
// u = (t - t0)/(t1 - t0), also beyond the knots; the velocity is (B - A)/(t1 - t0).
TEST(PoseMotion, LinearMixesTheMatricesAndExtrapolates) {
  const Affine2 M = pose(3.0, 1.0, 0.0, 2.0, 4.0, -2.0);
  const PoseMotion linear(PoseMethod::linear, {{0.0, kA}, {2.0, M}});
  EXPECT_LT(distance(linear.at(0.5), pose(1.5, 0.25, 0.0, 1.25, 1.0, -0.5)), 1e-15);   // u = 1/4
  EXPECT_LT(distance(linear.at(3.0), pose(4.0, 1.5, 0.0, 2.5, 6.0, -3.0)), 1e-14);     // u = 3/2
  EXPECT_LT(distance(linear.at(-2.0), pose(-1.0, -1.0, 0.0, 0.0, -4.0, 2.0)), 1e-14);  // u = -1
  for (const double t : {0.3, 1.0, 2.5}) {
    EXPECT_LT(distance(linear.velocity(t), pose(1.0, 0.5, 0.0, 0.5, 2.0, -1.0)), 1e-15) << t;
  }
}

// The SAM from the identity to a quarter turn about (1, 0) is the rotation
// about (1, 0) through t pi/2: x -> R(t pi/2) (x - c) + c.
TEST(PoseMotion, SamOfAQuarterTurnTurnsAboutItsCentreAtConstantSpeed) {
  const Affine2 quarter = pose(0.0, -1.0, 1.0, 0.0, 1.0, -1.0);
  const PoseMotion motion(PoseMethod::sam, {{0.0, kA}, {1.0, quarter}});
  for (const double t : {0.25, 0.5, 1.5}) {
    const double angle = t * std::numbers::pi / 2.0, c = std::cos(angle), s = std::sin(angle);
    // b = c0 - R c0 with c0 = (1, 0).
    EXPECT_LT(distance(motion.at(t), pose(c, -s, s, c, 1.0 - c, -s)), 1e-14) << t;
  }
}

TEST(PoseMotion, RefusesWrongPoseCountsAndUnorderedKnots) {
  EXPECT_THROW(PoseMotion(PoseMethod::sam, {{0.0, kA}, {0.5, kB}, {1.0, kA}}), std::invalid_argument);
  EXPECT_THROW(PoseMotion(PoseMethod::poly_sam, {{0.0, kA}}), std::invalid_argument);
  EXPECT_THROW(PoseMotion(PoseMethod::biarc_sam, {{0.0, kA}, {1.0, kB}}), std::invalid_argument);
  EXPECT_THROW(PoseMotion(PoseMethod::linear, {{1.0, kA}, {1.0, kB}}), std::invalid_argument);
  EXPECT_THROW(PoseMotion(PoseMethod::poly_sam, {{0.0, kA}, {2.0, kB}, {1.0, kA}}), std::invalid_argument);
  EXPECT_THROW(PoseMotion(PoseMethod::four_point, {{0.0, kA}, {1.0, kB}, {2.0, kA}}, kMaxSubdivisions + 1),
               std::invalid_argument);
}

// Bezier SAM and bi-arc are not defined beyond their end poses: clamped there.
TEST(PoseMotion, BezierAndBiarcAreClampedOutsideTheKnots) {
  const std::vector<TimedPose> poses = {{0.0, kA}, {0.4, kB}, {1.0, kC}};
  for (const PoseMethod method : {PoseMethod::bezier_sam, PoseMethod::biarc_sam}) {
    const PoseMotion motion(method, poses);
    EXPECT_LT(distance(motion.at(-0.5), kA), 1e-12) << info(method).id;
    EXPECT_LT(distance(motion.at(1.7), kC), 1e-12) << info(method).id;
  }
}

// The morphs Fig. 2 compares with SAM, through PoseMotion: scene times mapped
// onto [0, 1], exact poses at the knots, velocity by the chain rule, the
// reference triangle passed on (TSB blends its sides), opposite orientations
// refused.
TEST(PoseMotion, Fig2MorphsThroughTimedPoses) {
  const Affine2 from = pose(2.2, 0.6, 0.3, 1.6, 0.0, 0.0);
  const Affine2 to = pose(0.7, -1.6, 2.4, 1.1, 6.5, 0.5);
  const std::array<Point, 3> reference{Point{0.0, 0.0}, Point{2.0, 0.0}, Point{0.5, 1.5}};
  for (const PoseMethod method : {PoseMethod::rarap, PoseMethod::asap, PoseMethod::tsb}) {
    SCOPED_TRACE(info(method).id);
    const PoseMotion motion(method, {{2.0, from}, {5.0, to}}, kDefaultSubdivisions, reference);
    EXPECT_EQ(distance(motion.at(2.0), from), 0.0);
    EXPECT_EQ(distance(motion.at(5.0), to), 0.0);
    for (const double t : {2.5, 3.5, 4.9}) {
      const double h = 1e-6;
      const Affine2 before = motion.at(t - h), after = motion.at(t + h);
      const Affine2 expected{(after.L - before.L) / (2.0 * h), (after.b - before.b) / (2.0 * h)};
      EXPECT_LT(distance(motion.velocity(t), expected), 1e-6 * (1.0 + expected.L.norm() + expected.b.norm()))
          << "t = " << t;
    }
    EXPECT_THROW(PoseMotion(method, {{0.0, from}, {1.0, pose(1.0, 0.0, 0.0, -1.0, 0.0, 0.0)}}), std::invalid_argument);
    EXPECT_THROW(PoseMotion(method, {{0.0, from}, {1.0, to}, {2.0, from}}), std::invalid_argument);
  }
  // The reference triangle matters to TSB (its sides) and rARAP (its barycentre).
  const PoseMotion unit(PoseMethod::tsb, {{0.0, from}, {1.0, to}});
  const PoseMotion other(PoseMethod::tsb, {{0.0, from}, {1.0, to}}, kDefaultSubdivisions, reference);
  EXPECT_GT(distance(unit.at(0.5), other.at(0.5)), 1e-3);
}

TEST(PoseMethods, TableNamesEachMethodOnceWithItsPoseCounts) {
  std::set<std::string> ids;
  for (const PoseMethodInfo& entry : all_pose_methods()) {
    EXPECT_TRUE(ids.insert(std::string(entry.id)).second) << entry.id;
    EXPECT_EQ(&info(entry.method), &entry) << entry.id;
    EXPECT_LE(entry.min_poses, entry.max_poses) << entry.id;
  }
  EXPECT_EQ(ids.size(), 14u);  // the SAM paper's ten and the pose PITAs P4, P5, P6, P9
  for (const PoseMethod method : {PoseMethod::rarap, PoseMethod::asap, PoseMethod::tsb, PoseMethod::alexa}) {
    EXPECT_EQ(info(method).min_poses, 2);
    EXPECT_EQ(info(method).max_poses, 2);
  }
  EXPECT_EQ(info(PoseMethod::sam).id, "SAM");
  EXPECT_EQ(info(PoseMethod::sam).min_poses, 2);
  EXPECT_EQ(info(PoseMethod::sam).max_poses, 2);
  EXPECT_EQ(info(PoseMethod::biarc_sam).min_poses, 3);
  EXPECT_EQ(info(PoseMethod::biarc_sam).max_poses, 3);
}

}  // namespace
}  // namespace pita
