// Ease functions (src/core/ease.cpp): CSS cubic-bezier timing against an
// independent bisection solver written here, the chapter's sine, sine-cap and
// parabolic eases against their defining properties (chapter Eq. 3.18-3.22,
// docs/paper-notes.md N16, N20).
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/ease.hpp"

namespace pita {
namespace {

// CSS cubic-bezier by plain bisection on x(s) (no Newton), 200 halvings.
double css_reference(double x1, double y1, double x2, double y2, double x) {
  const auto coordinate = [](double p1, double p2, double s) {
    return 3 * (1 - s) * (1 - s) * s * p1 + 3 * (1 - s) * s * s * p2 + s * s * s;
  };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (coordinate(x1, x2, mid) < x ? lo : hi) = mid;
  }
  return coordinate(y1, y2, 0.5 * (lo + hi));
}

double slope(const Ease& e, double x, double h = 1e-6) { return (ease(e, x + h) - ease(e, x - h)) / (2 * h); }

TEST(Ease, EveryEaseFixesTheEnds) {
  std::vector<Ease> eases;
  for (const NamedEase& named : named_eases()) eases.push_back(named.ease);
  eases.push_back(cubic_bezier_ease(0.1, -0.5, 0.9, 1.5));
  eases.push_back(sine_cap_ease(0.2, 0.7));
  eases.push_back(parabolic_ease(0.3, 0.6));
  eases.push_back(sine_cap_ease(0.0, 1.0));
  eases.push_back(parabolic_ease(0.0, 0.0));
  eases.push_back(parabolic_ease(1.0, 1.0));
  for (const Ease& e : eases) {
    SCOPED_TRACE(ease_label(e));
    EXPECT_EQ(ease(e, 0.0), 0.0);
    EXPECT_EQ(ease(e, 1.0), 1.0);
    EXPECT_EQ(ease(e, -0.5), 0.0);  // clamped
    EXPECT_EQ(ease(e, 1.5), 1.0);
  }
}

TEST(Ease, CssNamedCurvesMatchAnIndependentSolverTo1e12) {
  struct Named {
    const char* name;
    double x1, y1, x2, y2;
  };
  for (const Named& n : {Named{"ease", 0.25, 0.1, 0.25, 1.0}, Named{"ease-in", 0.42, 0.0, 1.0, 1.0},
                         Named{"ease-out", 0.0, 0.0, 0.58, 1.0}, Named{"ease-in-out", 0.42, 0.0, 0.58, 1.0}}) {
    SCOPED_TRACE(n.name);
    const std::optional<Ease> e = find_named_ease(n.name);
    ASSERT_TRUE(e.has_value());
    for (int i = 0; i <= 1000; ++i) {
      const double x = i / 1000.0;
      EXPECT_NEAR(ease(*e, x), css_reference(n.x1, n.y1, n.x2, n.y2, x), 1e-12) << "x = " << x;
    }
  }
}

TEST(Ease, CubicBezierWithOvershootAndFlatEndsMatchesTheSolver) {
  // y outside [0, 1] (CSS allows it) and x1 = x2 = 0 or 1 (flat ends).
  for (const auto& p : {std::array<double, 4>{0.3, -0.6, 0.7, 1.6}, std::array<double, 4>{0.0, 0.0, 1.0, 1.0},
                        std::array<double, 4>{0.1, 0.9, 0.2, 0.8}, std::array<double, 4>{0.9, 0.1, 0.8, 0.2}}) {
    const Ease e = cubic_bezier_ease(p[0], p[1], p[2], p[3]);
    for (int i = 0; i <= 400; ++i) {
      const double x = i / 400.0;
      EXPECT_NEAR(ease(e, x), css_reference(p[0], p[1], p[2], p[3], x), 1e-12) << ease_label(e) << " x = " << x;
    }
  }
}

TEST(Ease, CubicBezierParameterSolvesXToRounding) {
  // Also where x'(s) = 0 inside (x1 = 1, x2 = 0: y has a vertical tangent and
  // no solver can give y to 1e-12 there, but s still solves x(s) = x).
  const auto x_of = [](double x1, double x2, double s) {
    return 3 * (1 - s) * (1 - s) * s * x1 + 3 * (1 - s) * s * s * x2 + s * s * s;
  };
  for (const auto& p : {std::array<double, 2>{1.0, 0.0}, std::array<double, 2>{0.0, 1.0},
                        std::array<double, 2>{0.42, 0.58}, std::array<double, 2>{0.0, 0.0}}) {
    for (int i = 0; i <= 1000; ++i) {
      const double x = i / 1000.0;
      const double s = cubic_bezier_parameter(p[0], p[1], x);
      EXPECT_GE(s, 0.0);
      EXPECT_LE(s, 1.0);
      EXPECT_NEAR(x_of(p[0], p[1], s), x, 1e-15) << p[0] << ", " << p[1] << " at x = " << x;
    }
  }
}

TEST(Ease, CubicBezierIdentityIsLinear) {
  const Ease e = cubic_bezier_ease(1.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0);
  for (int i = 0; i <= 100; ++i) EXPECT_NEAR(ease(e, i / 100.0), i / 100.0, 1e-14);
}

TEST(Ease, CubicBezierRefusesXOutsideTheUnitInterval) {
  EXPECT_THROW(cubic_bezier_ease(-0.1, 0, 1, 1), std::invalid_argument);
  EXPECT_THROW(cubic_bezier_ease(0.5, 0, 1.01, 1), std::invalid_argument);
  EXPECT_THROW(cubic_bezier_ease(0.5, NAN, 0.5, 1), std::invalid_argument);
  EXPECT_NO_THROW(cubic_bezier_ease(0.5, -3, 0.5, 4));
}

TEST(Ease, SineIsTheChaptersEq318WithItsQuotedValues) {
  const Ease e = *find_named_ease("sine");
  // "at t = 0.25, ease(t) = 0.1465, and at t = 0.75, ease(t) = 0.8535" (Sec. 3.2.3).
  EXPECT_NEAR(ease(e, 0.25), 0.1465, 1e-4);
  EXPECT_NEAR(ease(e, 0.75), 0.8535, 1e-4);
  for (int i = 0; i <= 100; ++i) {
    const double x = i / 100.0;
    EXPECT_NEAR(ease(e, x), (1.0 - std::cos(kPi * x)) / 2.0, 1e-15);
  }
  EXPECT_NEAR(slope(e, 1e-4), 0.0, 1e-3);  // starts from rest
}

TEST(Ease, SineCapIsC1WithUnitSlopeBetweenK1AndK2ScaledByF) {
  const double k1 = 0.3, k2 = 0.75;
  const Ease e = sine_cap_ease(k1, k2);
  const double f = 2 * k1 / kPi + k2 - k1 + 2 * (1 - k2) / kPi;                    // total distance before normalising
  for (double x : {0.35, 0.5, 0.7}) EXPECT_NEAR(slope(e, x), 1.0 / f, 1e-8) << x;  // constant speed
  for (double x : {k1, k2}) EXPECT_NEAR(slope(e, x - 1e-4), slope(e, x + 1e-4), 1e-3) << "C1 at " << x;
  EXPECT_NEAR(slope(e, 1e-5), 0.0, 1e-3);
  EXPECT_NEAR(slope(e, 1 - 1e-5), 0.0, 1e-3);
}

TEST(Ease, SineCapWithEqualHalvesIsTheSineEase) {
  const Ease cap = sine_cap_ease(0.5, 0.5), sine = *find_named_ease("sine");
  for (int i = 0; i <= 100; ++i) EXPECT_NEAR(ease(cap, i / 100.0), ease(sine, i / 100.0), 1e-15);
}

TEST(Ease, ParabolicHasConstantAccelerationThenSpeedV0ThenDeceleration) {
  const double t1 = 0.2, t2 = 0.65;
  const Ease e = parabolic_ease(t1, t2);
  const double v0 = 2.0 / (t2 - t1 + 1.0);  // chapter Eq. 3.22 (as corrected, N16)
  for (double x : {0.3, 0.45, 0.6}) EXPECT_NEAR(slope(e, x), v0, 1e-8) << x;
  // Constant acceleration v0 / t1 and deceleration v0 / (1 - t2): second differences.
  const auto second = [&](double x) {
    const double h = 1e-4;
    return (ease(e, x + h) - 2 * ease(e, x) + ease(e, x - h)) / (h * h);
  };
  EXPECT_NEAR(second(0.1), v0 / t1, 1e-4);
  EXPECT_NEAR(second(0.8), -v0 / (1 - t2), 1e-4);
  // chapter Eq. 3.21: the areas under the speed add up to one, so ease(t1) = v0 t1 / 2.
  EXPECT_NEAR(ease(e, t1), v0 * t1 / 2, 1e-15);
}

TEST(Ease, ParabolicWithEqualTimesIsPiecewiseQuadratic) {
  const Ease e = parabolic_ease(0.5, 0.5);  // v0 = 2
  for (int i = 0; i <= 100; ++i) {
    const double x = i / 100.0;
    EXPECT_NEAR(ease(e, x), x < 0.5 ? 2 * x * x : 1 - 2 * (1 - x) * (1 - x), 1e-15);
  }
}

TEST(Ease, OrderOfTheParametersIsChecked) {
  EXPECT_THROW(sine_cap_ease(0.8, 0.2), std::invalid_argument);
  EXPECT_THROW(sine_cap_ease(-0.1, 0.2), std::invalid_argument);
  EXPECT_THROW(parabolic_ease(0.6, 0.5), std::invalid_argument);
  EXPECT_THROW(parabolic_ease(0.1, 1.5), std::invalid_argument);
}

TEST(Ease, EveryEaseIsMonotoneWhenItsControlPointsAre) {
  for (const NamedEase& named : named_eases()) {
    double previous = 0.0;
    for (int i = 1; i <= 1000; ++i) {
      const double y = ease(named.ease, i / 1000.0);
      EXPECT_GE(y, previous) << named.name << " at " << i / 1000.0;
      previous = y;
    }
  }
}

TEST(Ease, LabelsNameTheEase) {
  EXPECT_EQ(ease_label(*find_named_ease("ease-in-out")), "ease-in-out");
  EXPECT_EQ(ease_label(cubic_bezier_ease(0.1, 0.2, 0.3, 0.4)), "cubic-bezier(0.1, 0.2, 0.3, 0.4)");
  EXPECT_EQ(ease_label(parabolic_ease(0.25, 0.75)), "parabolic(t1 0.25, t2 0.75)");
  EXPECT_EQ(find_named_ease("Ease-In"), std::nullopt);  // the scene reader lower-cases names
}

}  // namespace
}  // namespace pita
