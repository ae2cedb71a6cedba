// The knot warp of P4, P7 and P8 (src/core/knot_warp.cpp): knots to 0, 1/2, 1,
// identity for even knots, increasing, C1 and symmetric (PITA Eq. 41).
#include <cmath>

#include "core/knot_warp.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

TEST(KnotWarp, SendsKnotsToZeroHalfOne) {
  for (double beta : {0.1, 0.3, 0.5, 0.66, 0.9}) {
    EXPECT_NEAR(knot_warp(2.0, 2.0 + 3.0 * beta, 5.0, 2.0), 0.0, 1e-15);
    EXPECT_NEAR(knot_warp(2.0, 2.0 + 3.0 * beta, 5.0, 2.0 + 3.0 * beta), 0.5, 1e-15);
    EXPECT_NEAR(knot_warp(2.0, 2.0 + 3.0 * beta, 5.0, 5.0), 1.0, 1e-15);
  }
}

TEST(KnotWarp, IsIdentityForEvenKnots) {
  for (double t : {-1.0, 0.0, 0.3, 0.5, 0.77, 1.0, 2.5}) {
    EXPECT_NEAR(knot_warp(0.0, 0.5, 1.0, t), t, 1e-15);
  }
}

TEST(KnotWarp, IsIncreasingC1AndSymmetric) {
  for (double beta : {0.05, 0.2, 0.4, 0.66, 0.95}) {
    const auto u = [&](double s) { return knot_warp(0.0, beta, 1.0, s); };
    double prev = u(-1.0);
    for (int i = 1; i <= 3000; ++i) {
      const double s = -1.0 + 3.0 * i / 3000.0;
      EXPECT_GT(u(s), prev) << "beta=" << beta << " s=" << s;
      prev = u(s);
      // Symmetry: u(1 - s; 1 - beta) = 1 - u(s; beta) (PITA Eq. 41 for P4, P7, P8).
      EXPECT_NEAR(knot_warp(0.0, 1.0 - beta, 1.0, 1.0 - s), 1.0 - u(s), 1e-12);
    }
    // C1 at 0, beta and 1: one-sided slopes agree to O(h).
    const double h = 1e-7;
    for (double s0 : {0.0, beta, 1.0}) {
      const double left = (u(s0) - u(s0 - h)) / h;
      const double right = (u(s0 + h) - u(s0)) / h;
      EXPECT_NEAR(left, right, 1e-5 * (1 + std::abs(left))) << "beta=" << beta << " at " << s0;
    }
    EXPECT_NEAR((u(beta + h) - u(beta - h)) / (2 * h), 1.0, 1e-4);  // kink in u'' at beta
  }
}

// The two quadratic pieces and the linear ends of core/knot_warp.hpp, worked
// by hand for beta = 1/4 (kappa = -1/2): at sigma = 1/2, h = 1/2 + 1/8.
TEST(KnotWarp, FollowsItsQuadraticPiecesAndLinearEnds) {
  // Knots 2, 3, 6: s = (t - 2)/4, beta = 1/4.
  EXPECT_NEAR(knot_warp(2.0, 3.0, 6.0, 2.5), 0.3125, 1e-15);  // s = 1/8: 1/2 h(1/2)
  EXPECT_NEAR(knot_warp(2.0, 3.0, 6.0, 4.5), 0.8125, 1e-15);  // s = 5/8: 1/2 + 1/2 h(1/2)
  // Slopes at the ends: (1 - beta)/beta = 3 before a, beta/(1 - beta) = 1/3 after c.
  EXPECT_NEAR(knot_warp(2.0, 3.0, 6.0, -2.0), -3.0, 1e-14);             // s = -1
  EXPECT_NEAR(knot_warp(2.0, 3.0, 6.0, 10.0), 1.0 + 1.0 / 3.0, 1e-14);  // s = 2
}

// Knots out of order (b outside (a, c), PITA Eq. 42): the quadratic through (a, 0),
// (b, 1/2), (c, 1). For a = 0, b = 2, c = 1 it is u = 7/4 t - 3/4 t^2.
TEST(KnotWarp, OutOfOrderKnotsGiveTheLagrangeQuadratic) {
  for (const double t : {-1.0, 0.0, 0.5, 1.0, 2.0, 3.0}) {
    EXPECT_NEAR(knot_warp(0.0, 2.0, 1.0, t), 1.75 * t - 0.75 * t * t, 1e-14) << t;
  }
}

}  // namespace
}  // namespace pita::test
