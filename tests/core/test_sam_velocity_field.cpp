// The stationary velocity field of a SAM (src/core/sam_velocity_field.hpp;
// SAM paper Sec. 6.2, SAM Eq. 7, Fig. 8), against an independent oracle: Eigen's
// generic matrix log and exp (MatrixFunctions) and the fixed point solved
// directly, and against the SAM's own samples by finite differences.
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/affine_power.hpp"
#include "core/sam_velocity_field.hpp"
#include "core/steady_affine_morph.hpp"
#include "support/matrix_functions.hpp"

namespace pita {
namespace {

Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

// Fig. 8's SAM (scenes/sam-fig08-velocity-field.json): about q = (3, 2),
// L = R(110 deg) [[1.35, 0.25], [0, 0.8]].
Affine2 fig8_affinity() {
  Eigen::Matrix2d S;
  S << 1.35, 0.25, 0.0, 0.8;
  const Eigen::Matrix2d L = rotation(110.0 * std::numbers::pi / 180.0) * S;
  const Eigen::Vector2d q(3.0, 2.0);
  return {L, q - L * q};
}

TEST(SamVelocityField, IsEquation7WithTheFixedPoint) {
  const Affine2 A = fig8_affinity();
  const SamVelocityField field(A);
  // Independently: log L by Eigen's Schur-Parlett log, q from (I - L) q = b.
  const Eigen::Matrix2d log_L = oracle::log(A.L);
  const Eigen::Vector2d q = (Eigen::Matrix2d::Identity() - A.L).partialPivLu().solve(A.b);
  ASSERT_TRUE(field.fixed_point().has_value());
  EXPECT_NEAR((*field.fixed_point() - q).norm(), 0.0, 1e-12);
  for (const Eigen::Vector2d& x :
       {Eigen::Vector2d(-1.0, -2.6), Eigen::Vector2d(7.0, 5.4), Eigen::Vector2d(3.0, 2.0), Eigen::Vector2d(0.5, 4.0)}) {
    const Eigen::Vector2d expected = log_L * (x - q);  // SAM Eq. 7, t_N = 0 (1 is no eigenvalue)
    EXPECT_NEAR((field.at(x) - expected).norm(), 0.0, 1e-12) << x.transpose();
  }
  // Linear in the distance from q (the caption): v(q + s d) = s v(q + d).
  const Eigen::Vector2d d(1.3, -0.4);
  EXPECT_NEAR((field.at(q + 2.5 * d) - 2.5 * field.at(q + d)).norm(), 0.0, 1e-12);
}

TEST(SamVelocityField, TrajectoriesAreTheSamPathsOfThePoints) {
  // The SAM between two poses: the trajectory of x0 = B(p) is SAM(u)(p),
  // and equals exp(u log A)(x0) by Eigen's generic 3x3 log and exp.
  Affine2 B;
  B.L << 2.0, 0.5, 0.0, 1.6;
  B.b << 0.5, 0.2;
  const Affine2 C = compose(fig8_affinity(), B);
  const SamVelocityField field = SamVelocityField::between(B, C);
  const SteadyAffineMorph sam(B, C);
  Eigen::Matrix3d H = Eigen::Matrix3d::Identity();
  H.topLeftCorner<2, 2>() = fig8_affinity().L;
  H.topRightCorner<2, 1>() = fig8_affinity().b;
  const Eigen::Matrix3d log_H = oracle::log(H);
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.3, 0.9)}) {
    const Eigen::Vector2d x0 = apply(B, p);
    for (const double u : {0.0, 0.2, 0.5, 0.9, 1.0, 1.7}) {
      EXPECT_NEAR((field.trajectory(x0, u) - apply(sam.at(u), p)).norm(), 0.0, 1e-11) << u;
      const Eigen::Vector3d oracle = oracle::exp(Eigen::Matrix3d(u * log_H)) * Eigen::Vector3d(x0.x(), x0.y(), 1.0);
      EXPECT_NEAR((field.trajectory(x0, u) - oracle.head<2>()).norm(), 0.0, 1e-11) << u;
    }
  }
}

TEST(SamVelocityField, FieldIsTheFiniteDifferenceDerivativeAtEveryTime) {
  Affine2 B;
  B.L << 1.0, 0.3, -0.2, 0.9;
  B.b << -1.0, 0.4;
  const Affine2 C = compose(fig8_affinity(), B);
  const SamVelocityField field = SamVelocityField::between(B, C);
  const SteadyAffineMorph sam(B, C);
  const double h = 1e-4;
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(2.0, -1.0)}) {
    for (const double u : {-0.5, 0.0, 0.3, 0.75, 1.0, 2.0}) {
      const Eigen::Vector2d derivative = (apply(sam.at(u + h), p) - apply(sam.at(u - h), p)) / (2.0 * h);
      const Eigen::Vector2d at = apply(sam.at(u), p);
      EXPECT_NEAR((derivative - field.at(at)).norm(), 0.0, 1e-6 * field.at(at).norm()) << u;
    }
  }
}

TEST(SamVelocityField, VelocityIsConstantInTheMovingFrame) {
  // Property (6) of Sec. 2.3: in the frame of the moving pose, the velocity
  // of a point, A_u^-1's linear part applied to it, does not change with u.
  Affine2 B;
  B.L << 1.5, 0.0, 0.4, 0.7;
  B.b << 0.3, -0.2;
  const Affine2 C = compose(fig8_affinity(), B);
  const SamVelocityField field = SamVelocityField::between(B, C);
  const SteadyAffineMorph sam(B, C);
  const Eigen::Vector2d p(0.7, 0.4);
  const auto local = [&](double u) {
    const Affine2 pose = sam.at(u);
    return Eigen::Vector2d(pose.L.inverse() * field.at(apply(pose, p)));
  };
  for (const double u : {0.25, 0.5, 1.0, 1.5}) EXPECT_NEAR((local(u) - local(0.0)).norm(), 0.0, 1e-12) << u;
}

TEST(SamVelocityField, TranslationHasAConstantFieldAndNoFixedPoint) {
  // S1 (1 is an eigenvalue): no unique q; SAM Eq. 7's t_N is the whole translation.
  const Affine2 A{Eigen::Matrix2d::Identity(), Eigen::Vector2d(2.0, -1.0)};
  const SamVelocityField field(A);
  EXPECT_FALSE(field.fixed_point().has_value());
  for (const Eigen::Vector2d& x : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(-5.0, 3.0)}) {
    EXPECT_NEAR((field.at(x) - Eigen::Vector2d(2.0, -1.0)).norm(), 0.0, 1e-15);
  }
}

TEST(SamVelocityField, NoSamNoField) {
  // L = diag(-2, -0.5): two negative eigenvalues, no real log (G3).
  Eigen::Matrix2d L;
  L << -2.0, 0.0, 0.0, -0.5;
  EXPECT_THROW(SamVelocityField(Affine2{L, Eigen::Vector2d::Zero()}), NoRealLogarithm);
}

}  // namespace
}  // namespace pita
