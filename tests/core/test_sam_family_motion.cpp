// The SAM family in space (src/core/sam_family_motion.cpp, SamFamilyMotion<Affine3>):
// every method checked against its stated properties, SAM and polySAM against
// an independent power (Eigen's Schur-Pade in long double), and against the
// 2D PoseMotion on poses that keep the plane z = 0 and the z axis: there each
// 3D motion must be the 2D motion with z carried along. (Both dimensions run
// the same template, tested in 2D by test_pose_motion.cpp and
// test_sam_splines.cpp; the comparison checks the 3D SAM under it.)
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/pose_motion.hpp"
#include "core/sam_family_motion.hpp"
#include "pose_test_support.hpp"
#include "support/matrix_functions.hpp"

namespace pita {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

double distance3(const Affine3& X, const Affine3& Y) { return (X.L - Y.L).norm() + (X.b - Y.b).norm(); }

// The plane pose P as a pose of space that scales z by `z_scale` and lifts it by `z_shift`.
Affine3 embedded(const Affine2& P, double z_scale = 1.0, double z_shift = 0.0) {
  Affine3 A;
  A.L.topLeftCorner<2, 2>() = P.L;
  A.L(2, 2) = z_scale;
  A.b.head<2>() = P.b;
  A.b(2) = z_shift;
  return A;
}

Affine3 screw(const Vector3d& axis, double angle, double scale, const Vector3d& b) {
  return {scale * Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(), b};
}

// Three poses of space with SAMs between consecutive ones.
const std::vector<TimedPoseOf<Affine3>> kPoses = {
    {0.0, Affine3::identity()},
    {0.4, screw(Vector3d(1, 2, 3), 1.1, 1.3, Vector3d(2, -1, 0.5))},
    {1.0, screw(Vector3d(-1, 0.5, 2), 2.4, 0.8, Vector3d(4, 1, -2))},
};

// The independent reference: SAM(B, u, C) = (C B^-1)^u B with Eigen's
// Schur-Pade power of the 4x4 homogeneous matrix in long double.
Affine3 reference_sam(const Affine3& B, const Affine3& C, double u) {
  const Eigen::Matrix<long double, 4, 4> A = homogeneous(compose(C, inverse(B))).cast<long double>();
  const Eigen::Matrix<long double, 4, 4> P = oracle::pow(A, static_cast<long double>(u));
  return compose(affine3_of(Eigen::Matrix4d(P.cast<double>())), B);
}

TEST(SamFamilyInSpace, SamAndPolySamInterpolateAndMatchTheIndependentPower) {
  const SamFamilyMotion<Affine3> motion(PoseMethod::poly_sam, kPoses);
  for (const TimedPoseOf<Affine3>& p : kPoses) EXPECT_EQ(distance3(motion.at(p.t), p.pose), 0.0) << p.t;
  // Each span runs [t_i, t_i+1] onto [0, 1]; beyond the knots the end spans extrapolate.
  for (const double t : {-0.3, 0.1, 0.25, 0.55, 0.8, 1.4}) {
    const std::size_t i = t < 0.4 ? 0 : 1;
    const double u = (t - kPoses[i].t) / (kPoses[i + 1].t - kPoses[i].t);
    EXPECT_LT(distance3(motion.at(t), reference_sam(kPoses[i].pose, kPoses[i + 1].pose, u)), 1e-12) << t;
  }
  const SamFamilyMotion<Affine3> sam(PoseMethod::sam, {kPoses[0], kPoses[1]});
  EXPECT_LT(distance3(sam.at(0.2), reference_sam(kPoses[0].pose, kPoses[1].pose, 0.5)), 1e-12);
}

// SAM(S B, u, S C) = S SAM(B, u, C) for every affinity S (the SAM paper's
// invariance: (S C)(S B)^-1 = S (C B^-1) S^-1, whose powers are conjugates).
TEST(SamFamilyInSpace, EveryMethodCommutesWithAnAffineChangeOfFrame) {
  Affine3 S;
  S.L << 2.0, 0.3, -0.5, 0.1, 0.7, 0.2, -0.4, 0.0, 1.5;
  S.b = Vector3d(3.0, -2.0, 1.0);
  std::vector<TimedPoseOf<Affine3>> moved = kPoses;
  for (TimedPoseOf<Affine3>& p : moved) p.pose = compose(S, p.pose);
  for (const PoseMethod method : {PoseMethod::poly_sam, PoseMethod::bezier_sam, PoseMethod::biarc_sam,
                                  PoseMethod::linear, PoseMethod::four_point}) {
    const SamFamilyMotion<Affine3> original(method, kPoses, 2), transformed(method, moved, 2);
    for (const double t : {0.1, 0.4, 0.63, 0.9}) {
      const Affine3 expected = compose(S, original.at(t));
      EXPECT_LT(distance3(transformed.at(t), expected), 1e-11 * (1.0 + expected.L.norm() + expected.b.norm()))
          << info(method).id << " at t = " << t;
    }
  }
}

// On poses that keep the plane z = 0 (and scale z), every 3D method is the 2D
// method with z carried along: z scales by the SAM of the z scales (a power),
// linearly for "linear".
TEST(SamFamilyInSpace, EmbeddedPlanarPosesGiveTheTwoDimensionalMotion) {
  const std::vector<TimedPose> plane = {{0.0, test::kFig7A}, {0.4, test::kFig7B}, {1.0, test::kFig7C}};
  const std::vector<double> z_scales = {1.0, 2.0, 0.5};
  for (const PoseMethod method : {PoseMethod::poly_sam, PoseMethod::bezier_sam, PoseMethod::biarc_sam,
                                  PoseMethod::linear, PoseMethod::four_point}) {
    std::vector<TimedPoseOf<Affine3>> space;
    for (std::size_t i = 0; i < plane.size(); ++i) space.push_back({plane[i].t, embedded(plane[i].pose, z_scales[i])});
    const PoseMotion motion2(method, plane, 3);
    const SamFamilyMotion<Affine3> motion3(method, space, 3);
    for (const double t : {0.0, 0.15, 0.4, 0.7, 1.0}) {
      const Affine2 expected = motion2.at(t);
      const Affine3 got = motion3.at(t);
      EXPECT_LT((got.L.topLeftCorner<2, 2>() - expected.L).norm() + (got.b.head<2>() - expected.b).norm(), 1e-12)
          << info(method).id << " at t = " << t;
      const double coupling = got.L.topRightCorner<2, 1>().norm() + got.L.bottomLeftCorner<1, 2>().norm();
      EXPECT_LT(coupling + std::abs(got.b(2)), 1e-12) << info(method).id << " at t = " << t;
      EXPECT_GT(got.L(2, 2), 0.0);
    }
  }
}

TEST(SamFamilyInSpace, BezierEndsAndBiarcPassesTheMiddlePose) {
  const SamFamilyMotion<Affine3> bezier(PoseMethod::bezier_sam, kPoses);
  EXPECT_EQ(distance3(bezier.at(0.0), kPoses[0].pose), 0.0);
  EXPECT_LT(distance3(bezier.at(1.0), kPoses[2].pose), 1e-12);
  EXPECT_GT(distance3(bezier.at(0.4), kPoses[1].pose), 0.05);  // a control pose, not passed through
  const SamFamilyMotion<Affine3> biarc(PoseMethod::biarc_sam, kPoses);
  EXPECT_EQ(distance3(biarc.at(0.4), kPoses[1].pose), 0.0);
  EXPECT_LT(distance3(biarc.at(1.0), kPoses[2].pose), 1e-12);
  // Clamped outside the knots (the arcs are not defined beyond).
  EXPECT_EQ(distance3(biarc.at(-1.0), biarc.at(0.0)), 0.0);
  const SamFamilyMotion<Affine3> four(PoseMethod::four_point, kPoses, 3);
  for (const TimedPoseOf<Affine3>& p : kPoses) EXPECT_LT(distance3(four.at(p.t), p.pose), 1e-12) << p.t;
}

TEST(SamFamilyInSpace, VelocityIsTheDerivative) {
  for (const PoseMethod method :
       {PoseMethod::poly_sam, PoseMethod::linear, PoseMethod::bezier_sam, PoseMethod::biarc_sam}) {
    const SamFamilyMotion<Affine3> motion(method, kPoses);
    for (const double t : {0.1, 0.3, 0.55, 0.9}) {
      const double h = 1e-6;
      const Affine3 before = motion.at(t - h), after = motion.at(t + h);
      const Affine3 expected{(after.L - before.L) / (2.0 * h), (after.b - before.b) / (2.0 * h)};
      EXPECT_LT(distance3(motion.velocity(t), expected), 1e-6 * (1.0 + expected.L.norm() + expected.b.norm()))
          << info(method).id << " at t = " << t;
    }
  }
}

TEST(SamFamilyInSpace, RefusesTheMissingSamAndNamesThePair) {
  Affine3 no_log;
  no_log.L = Vector3d(-1.0, -2.0, 1.0).asDiagonal();
  try {
    const SamFamilyMotion<Affine3> motion(PoseMethod::poly_sam,
                                          {kPoses[0], kPoses[1], {2.0, compose(no_log, kPoses[1].pose)}});
    ADD_FAILURE() << "no error";
  } catch (const NoSamBetweenPoses& error) {
    EXPECT_EQ(error.first(), 1u);
    EXPECT_NE(std::string(error.what()).find("-2"), std::string::npos) << error.what();
  }
  // Linear needs no SAM.
  EXPECT_NO_THROW(SamFamilyMotion<Affine3>(PoseMethod::linear, {kPoses[0], {1.0, no_log}}));
  EXPECT_THROW(SamFamilyMotion<Affine3>(PoseMethod::rarap, {kPoses[0], kPoses[1]}), std::invalid_argument);
  EXPECT_THROW(SamFamilyMotion<Affine3>(PoseMethod::sam, kPoses), std::invalid_argument);  // SAM takes two
  EXPECT_THROW(SamFamilyMotion<Affine3>(PoseMethod::poly_sam, {kPoses[1], kPoses[0]}), std::invalid_argument);
}

}  // namespace
}  // namespace pita
