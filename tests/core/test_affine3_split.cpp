// The split of a 3x3 linear part (core/affine3_split.hpp, SAM A.6): an
// orthonormal right-handed basis whose first vector is an eigenvector, and
// the plane block standardised so that its diagonal entries are equal.
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include "core/affine3_split.hpp"

namespace pita::detail {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

void expect_right_handed_basis(const Matrix3d& Q) {
  EXPECT_LT((Q.transpose() * Q - Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(Q.determinant(), 1.0, 1e-14);
}

// 2 R_z(0.3) in a sheared basis: the real eigenvalue 2 belongs to the image
// of z, the rotation's axis; the plane block has the pair 2 e^{+-0.3 i}.
TEST(Affine3Split, SplitsOffTheRealEigenvalueOfAComplexPair) {
  Matrix3d R;
  R << std::cos(0.3), -std::sin(0.3), 0.0, std::sin(0.3), std::cos(0.3), 0.0, 0.0, 0.0, 1.0;
  Matrix3d S;
  S << 1.0, 0.4, 0.2, 0.0, 1.0, -0.3, 0.1, 0.0, 1.0;
  const Matrix3d L = S * (2.0 * R) * S.inverse();
  const Split split_L = split(L);
  expect_right_handed_basis(split_L.Q);
  EXPECT_NEAR(split_L.lambda_guess, 2.0, 1e-12);
  const Vector3d u = split_L.Q.col(0);
  EXPECT_LT((L * u - 2.0 * u).norm(), 1e-13);
  const Vector3d axis = (S * Vector3d::UnitZ()).normalized();
  EXPECT_NEAR(std::abs(u.dot(axis)), 1.0, 1e-13);
  int k = 0;
  u.cwiseAbs().maxCoeff(&k);
  EXPECT_GT(u(k), 0.0);  // the sign that fixes the half turn

  Matrix3d Q = split_L.Q;
  const Matrix3d T = standardised_split(L, Q);
  expect_right_handed_basis(Q);
  EXPECT_LT((T - Q.transpose() * L * Q).norm(), 1e-13);
  EXPECT_NEAR(T(1, 1), T(2, 2), 1e-13);                            // equal diagonal
  EXPECT_LT(std::abs(T(1, 0)) + std::abs(T(2, 0)), 1e-13);         // u an eigenvector
  EXPECT_NEAR(T(1, 1) * T(2, 2) - T(1, 2) * T(2, 1), 4.0, 1e-12);  // |2 e^{0.3 i}|^2
  EXPECT_NEAR(T(1, 1), 2.0 * std::cos(0.3), 1e-12);                // the pair's real part
}

// Three positive eigenvalues: the most isolated is split off (here 5, beside 1 and 1.2).
TEST(Affine3Split, SplitsOffTheMostIsolatedOfThreeReals) {
  const Matrix3d L = Vector3d(1.0, 5.0, 1.2).asDiagonal();
  const Split split_L = split(L);
  expect_right_handed_basis(split_L.Q);
  EXPECT_NEAR(split_L.lambda_guess, 5.0, 1e-12);
  EXPECT_LT((split_L.Q.col(0) - Vector3d::UnitY()).norm(), 1e-14);
}

}  // namespace
}  // namespace pita::detail
