// Lagrange weights (PITA Eq. 10) and Neville ratios (PITA Eq. 14), both header-only
// (core/lagrange_weights.hpp, core/neville_ratios.hpp).
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
  // PITA Eq. 12 with the ratios of PITA Eq. 14 equals PITA Eq. 11.
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

}  // namespace
}  // namespace pita::test
