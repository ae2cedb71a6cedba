// The instantaneous centers of a similarity motion (src/core/instant_center.cpp):
// on a rotation about a known point both centers are that point, and a
// translation has none.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "core/instant_center.hpp"

namespace pita {
namespace {

TEST(InstantCenter, RotationAndScalingAboutAPoint) {
  // x(t) = c + e^{L t} (x0 - c): every velocity is L (x - c), every
  // acceleration L^2 (x - c); both vanish at c only.
  const Point c{1.5, -2.0};
  const Complex L{0.3, 1.1};
  const double t = 0.7;
  const Point p0{0.0, 0.0}, q0{1.0, 0.5};
  const Complex e = std::exp(L * t);
  const Point p = c + e * (p0 - c), q = c + e * (q0 - c);
  const auto v = velocity_center(p, q, L * (p - c), L * (q - c));
  const auto a = acceleration_center(p, q, L * L * (p - c), L * L * (q - c));
  ASSERT_TRUE(v && a);
  EXPECT_NEAR(std::abs(*v - c), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(*a - c), 0.0, 1e-12);
  // The closed form (p q' - q p') / (q' - p') of the header agrees.
  const Vector dp = L * (p - c), dq = L * (q - c);
  EXPECT_NEAR(std::abs(*v - (p * dq - q * dp) / (dq - dp)), 0.0, 1e-12);
}

TEST(InstantCenter, TranslationHasNone) {
  EXPECT_FALSE(velocity_center({0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}, {2.0, 1.0}));
  // Nearly a translation: the zero lies beyond limits::kFarCenter |v|.
  EXPECT_FALSE(velocity_center({0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}, {2.0 + 1e-9, 1.0}));
  EXPECT_TRUE(velocity_center({0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}, {2.0 + 1e-3, 1.0}));
}

}  // namespace
}  // namespace pita
