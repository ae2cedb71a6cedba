// e^{tC} for C = x I + M (core/exp_of_parts.hpp, SAM Eq. 11) against closed
// forms: a Jordan block (gamma = 0), a rotation (gamma < 0), and a stretch
// whose eigenvalues are far apart (the projector branch, exact per entry).
#include <cmath>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/exp_of_parts.hpp"

namespace pita::detail {
namespace {

using Eigen::Matrix2d;

Matrix2d entries(double a, double b, double c, double d) {
  Matrix2d m;
  m << a, b, c, d;
  return m;
}

TEST(ExpOfParts, JordanBlockIsExact) {
  // C = 0.5 I + [[0, 2], [0, 0]]: e^{tC} = e^{t/2} [[1, 2t], [0, 1]].
  const Matrix2d M = entries(0.0, 2.0, 0.0, 0.0);
  for (const double t : {-1.5, 0.25, 3.0}) {
    const Matrix2d expected = std::exp(0.5 * t) * entries(1.0, 2.0 * t, 0.0, 1.0);
    EXPECT_LT((exp_of_parts(0.5, M, 0.0, t) - expected).norm(), 1e-14 * expected.norm()) << t;
  }
}

TEST(ExpOfParts, RotationIsTheRotationByTTheta) {
  const double theta = 2.5;
  const Matrix2d M = entries(0.0, -theta, theta, 0.0);  // M^2 = -theta^2 I
  for (const double t : {-0.7, 0.3, 1.0, 4.0}) {
    const double a = t * theta;
    const Matrix2d expected = entries(std::cos(a), -std::sin(a), std::sin(a), std::cos(a));
    EXPECT_LT((exp_of_parts(0.0, M, -theta * theta, t) - expected).norm(), 1e-14) << t;
  }
}

// diag(10, -10) at t = 3: e^30 and e^-30, each to a few ulps (cosh and sinh
// of 30 would leave nothing of e^-30).
TEST(ExpOfParts, FarApartEigenvaluesAreExactPerEntry) {
  const Matrix2d M = entries(10.0, 0.0, 0.0, -10.0);
  const Matrix2d E = exp_of_parts(0.0, M, 100.0, 3.0);
  EXPECT_NEAR(E(0, 0) / std::exp(30.0), 1.0, 1e-14);
  EXPECT_NEAR(E(1, 1) / std::exp(-30.0), 1.0, 1e-14);
  EXPECT_EQ(E(0, 1), 0.0);
  EXPECT_EQ(E(1, 0), 0.0);
}

// e^{tC} - I for a tiny t is t C to first order, with all its digits (no
// cancellation against I).
TEST(ExpOfParts, MinusIdentityKeepsTheDigitsOfSmallTimes) {
  const double theta = 1.2, x = 0.4, t = 1e-10;
  const Matrix2d M = entries(0.0, -theta, theta, 0.0);
  const Matrix2d D = exp_of_parts_minus_identity(x, M, -theta * theta, t);
  const Matrix2d C = x * Matrix2d::Identity() + M;
  // e^{tC} - I = tC + (tC)^2/2 + O(t^3).
  const Matrix2d expected = t * C + 0.5 * t * t * C * C;
  EXPECT_LT((D - expected).norm(), 1e-14 * expected.norm());
  for (const double s : {0.5, 2.0}) {
    const Matrix2d direct = exp_of_parts(x, M, -theta * theta, s) - Matrix2d::Identity();
    EXPECT_LT((exp_of_parts_minus_identity(x, M, -theta * theta, s) - direct).norm(), 1e-14) << s;
  }
}

}  // namespace
}  // namespace pita::detail
