// Alexa's log-matrix blend (core/log_matrix_blend.hpp), the motion the SAM
// paper compares SAM with in Sec. 3.3.2 and Figs. 4, 5: e^{(1-u) log B + u log C}.
#include <cmath>
#include <numbers>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/affine_power.hpp"
#include "core/log_matrix_blend.hpp"
#include "core/pose_motion.hpp"
#include "pose_test_support.hpp"
#include "support/matrix_functions.hpp"

namespace pita {
namespace {

using test::distance;
using test::pose;

Eigen::Matrix3d homogeneous(const Affine2& A) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Identity();
  H.topLeftCorner<2, 2>() = A.L;
  H.topRightCorner<2, 1>() = A.b;
  return H;
}

Affine2 affine(const Eigen::Matrix3d& H) { return {H.topLeftCorner<2, 2>(), H.topRightCorner<2, 1>()}; }

// The paper's example (Sec. 3.3.2, Fig. 4): B = Rotate(90 deg), C = Translate(6, 0).
const Affine2 kRotate90 = pose(0.0, -1.0, 1.0, 0.0, 0.0, 0.0);
const Affine2 kTranslate6 = pose(1.0, 0.0, 0.0, 1.0, 6.0, 0.0);

// Two general poses that do not commute.
const Affine2 kFrom = pose(1.3, 0.4, -0.2, 0.9, 1.0, -2.0);
const Affine2 kTo = pose(0.2, -1.4, 1.1, 0.6, 5.0, 3.0);

TEST(LogMatrixBlend, InterpolatesThePosesAtTheKnots) {
  const LogMatrixBlend blend(kFrom, kTo);
  EXPECT_LT(distance(blend.at(0.0), kFrom), 1e-14);
  EXPECT_LT(distance(blend.at(1.0), kTo), 1e-14);
  // Through PoseMotion the knots give the poses exactly, times mapped onto [0, 1].
  const PoseMotion motion(PoseMethod::alexa, {{2.0, kFrom}, {6.0, kTo}});
  EXPECT_EQ(distance(motion.at(2.0), kFrom), 0.0);
  EXPECT_EQ(distance(motion.at(6.0), kTo), 0.0);
  EXPECT_LT(distance(motion.at(3.0), blend.at(0.25)), 1e-15);
  EXPECT_LT(distance(motion.at(8.0), blend.at(1.5)), 1e-15);  // extrapolated
}

// The blend of absolute homogeneous logs, against Eigen's generic 3x3 log
// and exp (MatrixFunctions, an independent oracle of EAR's closed forms).
TEST(LogMatrixBlend, IsTheExpOfTheBlendedHomogeneousLogs) {
  const Eigen::Matrix3d log_B = oracle::log(homogeneous(kFrom)), log_C = oracle::log(homogeneous(kTo));
  const LogMatrixBlend blend(kFrom, kTo);
  for (const double u : {-0.3, 0.2, 0.5, 0.8, 1.4}) {
    const Eigen::Matrix3d expected = oracle::exp(Eigen::Matrix3d((1.0 - u) * log_B + u * log_C));
    EXPECT_NEAR(expected(2, 0), 0.0, 1e-12);
    EXPECT_LT(distance(blend.at(u), affine(expected)), 1e-12) << "u = " << u;
  }
}

// Sec. 3.3.2: for B = Rotate(90 deg) and C = Translate(6, 0), the mid-course
// transformations X = A_{1/2} (the pose at u = 1/2 is X o B) are
//   X_SAM   = [[1/r2, 1/r2, 3], [-1/r2, 1/r2, 3 r2 - 3]],
//   X_Alexa = [[1/r2, 1/r2, 6 r2/pi], [-1/r2, 1/r2, -6 (r2 - 2)/pi]],   r2 = sqrt(2);
// X_SAM is the rotation by -pi/4 about q = (3, -3), X_SAM^2 o B = C (the
// rotation by -pi/2 about q), while X_Alexa^2 o B is the translation by
// 12 sqrt(2)/pi ~ 5.402 in x.
TEST(LogMatrixBlend, ThePapersMidwayExample) {
  const double r2 = std::sqrt(2.0);
  const PoseMotion sam(PoseMethod::sam, {{0.0, kRotate90}, {1.0, kTranslate6}});
  const PoseMotion alexa(PoseMethod::alexa, {{0.0, kRotate90}, {1.0, kTranslate6}});
  const Affine2 x_sam = compose(sam.at(0.5), inverse(kRotate90));
  const Affine2 x_alexa = compose(alexa.at(0.5), inverse(kRotate90));
  EXPECT_LT(distance(x_sam, pose(1.0 / r2, 1.0 / r2, -1.0 / r2, 1.0 / r2, 3.0, 3.0 * r2 - 3.0)), 1e-14);
  EXPECT_LT(distance(x_alexa, pose(1.0 / r2, 1.0 / r2, -1.0 / r2, 1.0 / r2, 6.0 * r2 / kPi, -6.0 * (r2 - 2.0) / kPi)),
            1e-14);
  // Both turn by the same amount.
  EXPECT_LT((x_sam.L - x_alexa.L).norm(), 1e-15);
  // SAM: a rotation about q = (3, -3); squared, the pose C.
  const std::optional<Eigen::Vector2d> q = fixed_point(x_sam);
  ASSERT_TRUE(q.has_value());
  EXPECT_LT((*q - Eigen::Vector2d(3.0, -3.0)).norm(), 1e-14);
  const Affine2 rotation_about_q = compose(kTranslate6, inverse(kRotate90));  // R(-pi/2) about q
  EXPECT_LT(distance(compose(x_sam, x_sam), rotation_about_q), 1e-14);
  EXPECT_LT((apply(rotation_about_q, Eigen::Vector2d(3.0, -3.0)) - Eigen::Vector2d(3.0, -3.0)).norm(), 1e-15);
  EXPECT_LT(distance(compose(compose(x_sam, x_sam), kRotate90), kTranslate6), 1e-14);
  // Alexa: squared, a translation by 12 sqrt(2)/pi in x, short of C's 6.
  const Affine2 squared = compose(compose(x_alexa, x_alexa), kRotate90);
  EXPECT_LT(distance(squared, pose(1.0, 0.0, 0.0, 1.0, 12.0 * r2 / kPi, 0.0)), 1e-14);
  EXPECT_NEAR(squared.b.x(), 5.402, 5e-4);
  // Not steady: the mid-way pose is not the SAM's (|b_SAM - b_Alexa| = 0.32).
  EXPECT_GT(distance(x_sam, x_alexa), 0.3);
}

// "when B and C commute (for example if B = 1), the two solutions are
// identical" (Sec. 3.3.2).
TEST(LogMatrixBlend, EqualsTheSamWhenThePosesCommute) {
  const Affine2 M = pose(0.9, -0.7, 0.5, 1.1, 2.0, -1.0);
  const AffinePowers powers(M);
  const struct {
    const char* what;
    Affine2 B, C;
  } pairs[] = {
      {"B = identity", Affine2::identity(), kTo},
      {"powers of one affinity", powers.at(0.3), powers.at(1.7)},
      {"rotations about one point", pose(0.0, -1.0, 1.0, 0.0, 1.0, -1.0), pose(-0.6, -0.8, 0.8, -0.6, 1.6, -0.8)},
  };
  for (const auto& pair : pairs) {
    SCOPED_TRACE(pair.what);
    ASSERT_LT(distance(compose(pair.B, pair.C), compose(pair.C, pair.B)), 1e-14);  // they commute
    const LogMatrixBlend blend(pair.B, pair.C);
    const SteadyAffineMorph sam(pair.B, pair.C);
    for (const double u : {0.1, 0.5, 0.9, 1.3}) {
      EXPECT_LT(distance(blend.at(u), sam.at(u)), 1e-12) << "u = " << u;
    }
  }
}

// Velocity: the Frechet derivative of exp, against central differences.
TEST(LogMatrixBlend, VelocityIsTheDerivative) {
  const LogMatrixBlend blend(kFrom, kTo);
  const PoseMotion motion(PoseMethod::alexa, {{1.0, kFrom}, {3.0, kTo}});
  for (const double u : {-0.2, 0.0, 0.35, 0.7, 1.0}) {
    const double h = 1e-6;
    const Affine2 before = blend.at(u - h), after = blend.at(u + h);
    const Affine2 expected{(after.L - before.L) / (2.0 * h), (after.b - before.b) / (2.0 * h)};
    EXPECT_LT(distance(blend.velocity(u), expected), 1e-7 * (1.0 + expected.L.norm() + expected.b.norm()))
        << "u = " << u;
    // Scene time: d/dt = (d/du) / duration.
    const Affine2 rate = motion.velocity(1.0 + 2.0 * u);
    EXPECT_LT(distance(rate, Affine2{expected.L / 2.0, expected.b / 2.0}), 1e-6) << "u = " << u;
  }
}

// A pose without a real log (case G3, or mirrored) has no blend, even where
// a SAM exists: the typed "no SAM" error of PoseMotion, naming the pose.
TEST(LogMatrixBlend, RefusesPosesWithoutARealLog) {
  const Affine2 negative = pose(-2.0, 0.0, 0.0, -0.5, 3.0, 1.0);  // G3: eigenvalues -2, -0.5
  const Affine2 mirrored = pose(1.0, 0.0, 0.0, -1.0, 0.0, 0.0);
  try {
    LogMatrixBlend blend(kFrom, negative);
    FAIL() << "the second pose has no real log";
  } catch (const NoRealLogarithm& error) {
    EXPECT_EQ(error.root_case(), RootCase::G3);
    EXPECT_NE(std::string(error.what()).find("the second pose has no real logarithm"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(LogMatrixBlend(mirrored, kTo), NoRealLogarithm);
  EXPECT_THROW(PoseMotion(PoseMethod::alexa, {{0.0, negative}, {1.0, kTo}}), NoSamBetweenPoses);
  // Two mirrored poses have a SAM (C o B^-1 preserves orientation), not a blend.
  const Affine2 other_mirror = compose(pose(0.0, -1.0, 1.0, 0.0, 2.0, 0.0), mirrored);
  EXPECT_NO_THROW(PoseMotion(PoseMethod::sam, {{0.0, mirrored}, {1.0, other_mirror}}));
  try {
    PoseMotion motion(PoseMethod::alexa, {{0.0, mirrored}, {1.0, other_mirror}});
    FAIL() << "mirrored poses have no real log";
  } catch (const NoSamBetweenPoses& error) {
    EXPECT_EQ(error.first(), 0u);
    EXPECT_NE(std::string(error.what()).find("the first pose"), std::string::npos) << error.what();
  }
  // A SAM from a quarter turn to `negative` exists (C o B^-1 = [[0, -2], [0.5, 0]],
  // eigenvalues +-i, case G1), the blend does not.
  EXPECT_NO_THROW(PoseMotion(PoseMethod::sam, {{0.0, kRotate90}, {1.0, negative}}));
  EXPECT_THROW(PoseMotion(PoseMethod::alexa, {{0.0, kRotate90}, {1.0, negative}}), NoSamBetweenPoses);
}

}  // namespace
}  // namespace pita
