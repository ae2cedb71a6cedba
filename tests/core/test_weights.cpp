// Lagrange weights (Eq. 10), Neville ratios (Eq. 14) and the knot warp.
#include "core/knot_warp.hpp"
#include "core/lagrange_weights.hpp"
#include "core/neville_ratios.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

TEST(LagrangeWeights, InterpolateQuadraticsExactly) {
  Sampler s(20);
  for (int i = 0; i < 200; ++i) {
    const double a = s.uniform(-3, 0), b = a + s.uniform(0.1, 2), c = b + s.uniform(0.1, 2);
    const double k0 = s.uniform(-1, 1), k1 = s.uniform(-1, 1), k2 = s.uniform(-1, 1);
    const auto f = [&](double t) { return k0 + k1 * t + k2 * t * t; };
    const double t = s.uniform(-4, 4);
    const LagrangeWeights l = lagrange_weights(a, b, c, t);
    EXPECT_NEAR(l.x + l.y + l.z, 1.0, 1e-12);
    EXPECT_NEAR(lagrange(l, f(a), f(b), f(c)), f(t), 1e-10);
  }
  const LagrangeWeights at_b = lagrange_weights(0, 0.3, 1, 0.3);
  EXPECT_EQ(at_b.x, 0.0);
  EXPECT_EQ(at_b.y, 1.0);
  EXPECT_EQ(at_b.z, 0.0);
}

TEST(NevilleRatios, ReproduceTheLagrangeInterpolant) {
  // Eq. 12 with the ratios of Eq. 14 equals Eq. 11.
  Sampler s(21);
  for (int i = 0; i < 200; ++i) {
    const double a = 0, b = s.uniform(0.1, 0.9), c = 1;
    const Point pa = s.point(), pb = s.point(), pc = s.point();
    const double t = s.uniform(-1, 2);
    const NevilleRatios n = neville_ratios(a, b, c, t);
    const auto lerp = [](Point x, Point y, double u) { return x + u * (y - x); };
    const Point neville = lerp(lerp(pa, pb, n.q), lerp(pb, pc, n.r), n.s);
    EXPECT_NEAR(std::abs(neville - lagrange(lagrange_weights(a, b, c, t), pa, pb, pc)), 0.0, 1e-11);
  }
}

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
      // Symmetry: u(1 - s; 1 - beta) = 1 - u(s; beta) (Eq. 41 for P4, P7, P8).
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

}  // namespace
}  // namespace pita::test
