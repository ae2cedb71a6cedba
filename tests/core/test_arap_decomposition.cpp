// The ARAP decomposition L = R(alpha + beta) B (core/arap_decomposition.hpp,
// SAM paper Sec. 3.3.2): checked against the closed-form polar decomposition
// of a 2x2 matrix (rotation angle atan2(c - b, a + d), B = sqrt(L^T L)).
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "core/arap_decomposition.hpp"

namespace pita {
namespace {

Eigen::Matrix2d matrix(double a, double b, double c, double d) {
  Eigen::Matrix2d M;
  M << a, b, c, d;
  return M;
}

// The polar rotation's angle of L (det L > 0): L + cof(L) = [[a+d, b-c], [c-b, a+d]]
// is a positive multiple of it.
double polar_angle(const Eigen::Matrix2d& L) { return std::atan2(L(1, 0) - L(0, 1), L(0, 0) + L(1, 1)); }

void expect_decomposes(const Eigen::Matrix2d& L) {
  SCOPED_TRACE(::testing::Message() << "L = [" << L.row(0) << "; " << L.row(1) << "]");
  const ArapDecomposition d = arap_decomposition(L);
  // L = R(alpha + beta) B and = U^T Y V with U^T = R(alpha), V = R(beta).
  EXPECT_LT((pita::rotation(d.angle) * d.stretch - L).norm(), 1e-12 * L.norm());
  EXPECT_LT((pita::rotation(d.alpha) * d.singular.asDiagonal() * pita::rotation(d.beta) - L).norm(), 1e-12 * L.norm());
  // B = R(-beta) Y R(beta) is sqrt(L^T L): symmetric, positive eigenvalues, B^2 = L^T L.
  EXPECT_LT((d.stretch - d.stretch.transpose()).norm(), 1e-15 * L.norm());
  EXPECT_LT((d.stretch * d.stretch - L.transpose() * L).norm(), 1e-12 * L.squaredNorm());
  EXPECT_GT(d.singular(1), 0.0);
  EXPECT_GE(d.singular(0), d.singular(1));
  // The angle is the polar rotation's, in (-pi, pi], and alpha + beta modulo 2 pi.
  EXPECT_NEAR(d.angle, polar_angle(L), 1e-12);
  EXPECT_GT(d.angle, -std::numbers::pi);
  EXPECT_LE(d.angle, std::numbers::pi);
  const double turns = (d.alpha + d.beta - d.angle) / (2.0 * std::numbers::pi);
  EXPECT_NEAR(turns, std::round(turns), 1e-12);
}

TEST(ArapDecomposition, IsThePolarDecomposition) {
  expect_decomposes(matrix(2.2, 0.6, 0.3, 1.6));
  expect_decomposes(matrix(0.7, -1.6, 2.4, 1.1));
  expect_decomposes(matrix(1.0, 0.0, 0.0, 2.0));     // an SVD with reflections to exchange
  expect_decomposes(matrix(-1.0, 0.3, -0.2, -2.0));  // turning by nearly pi
  expect_decomposes(matrix(3.0, 0.0, 0.0, 3.0));     // a similarity: U, V not unique, U^T V is
}

// Rotation and stretch are recovered whatever the angles alpha and beta: their
// sum beyond pi comes back to (-pi, pi] (ARAP's recommendation).
TEST(ArapDecomposition, RecoversRotationAndStretch) {
  const Eigen::Matrix2d S = pita::rotation(-1.2) * Eigen::Vector2d(2.0, 0.5).asDiagonal() * pita::rotation(1.2);
  for (const double angle : {0.0, 0.4, -2.5, 3.0, -3.1, std::numbers::pi - 1e-9}) {
    SCOPED_TRACE(angle);
    const ArapDecomposition d = arap_decomposition(pita::rotation(angle) * S);
    EXPECT_NEAR(d.angle, angle, 1e-9);
    EXPECT_LT((d.stretch - S).norm(), 1e-12);
    EXPECT_NEAR(d.singular(0), 2.0, 1e-12);
    EXPECT_NEAR(d.singular(1), 0.5, 1e-12);
  }
}

// The half turn L = -2 I turns by +pi, whatever the signs of its zeros.
TEST(ArapDecomposition, HalfTurnIsPlusPi) {
  EXPECT_EQ(arap_decomposition(matrix(-2.0, 0.0, 0.0, -2.0)).angle, std::numbers::pi);
  EXPECT_EQ(arap_decomposition(matrix(-2.0, 0.0, -0.0, -2.0)).angle, std::numbers::pi);
  EXPECT_EQ(arap_decomposition(matrix(-2.0, -0.0, 0.0, -2.0)).angle, std::numbers::pi);
}

TEST(ArapDecomposition, RefusesReflectionsAndSingularParts) {
  EXPECT_THROW(arap_decomposition(matrix(1.0, 0.0, 0.0, -1.0)), std::invalid_argument);
  EXPECT_THROW(arap_decomposition(matrix(1.0, 2.0, 2.0, 4.0)), std::invalid_argument);
  EXPECT_THROW(arap_decomposition(matrix(NAN, 0.0, 0.0, 1.0)), std::invalid_argument);
}

}  // namespace
}  // namespace pita
