// Velocities, accelerations and instantaneous centers of D(t)
// (src/analysis/frame_derivatives.cpp; docs/paper-notes.md N40), checked
// against closed forms (the steady morph, P1's parabolas), the perseverance
// of P7 and P8 (PITA Sec. 3.3, PITA Eq. 35 and 39), and an independent
// difference of the motion at the centers.
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/frame_derivatives.hpp"
#include "motion/scene_motion.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {
namespace {

motion::SceneMotion motion_of(const std::string& method, const std::string& keyframes) {
  const scene::Scene scene =
      scene::parse_scene(R"({"method": ")" + method + R"(", "keyframes": [)" + keyframes + "]}", "s.json");
  return motion::build_motion(scene);
}

const std::string kEven = R"({"t": 0, "p": [0, 0], "m": 1.2, "w": 0.9},
    {"t": 0.5, "p": [3.5, 2.2], "m": 0.6, "w": 2.6}, {"t": 1, "p": [6.5, -0.5], "m": 1.5, "w": 4.0})";
const std::string kUneven = R"({"t": 0, "p": [0, 0], "m": 1.0, "w": 0.4},
    {"t": 1.3, "p": [3, 1.5], "m": 0.7, "w": 1.5}, {"t": 2, "p": [6, -0.5], "m": 1.4, "w": 2.2})";

double relative(Complex actual, Complex expected) {
  return std::abs(actual - expected) / std::max(1.0, std::abs(expected));
}

TEST(FrameDerivatives, SteadyMorphMatchesItsClosedForm) {
  // SMA from A (t = 0.5) to C (t = 2.5): x(t) = f + e^{L u} (x_A - f), u = (t - 0.5)/2,
  // L = ln(mC/mA) + i (wC - wA), f = (C.p - e^L A.p)/(1 - e^L) (reading note 1).
  const motion::SceneMotion motion = motion_of("SMA", R"({"t": 0.5, "p": [0, 0], "m": 1, "w": 0.3},
      {"t": 2.5, "p": [4, 1], "m": 2, "w": 2.5})");
  const Complex L{std::log(2.0), 2.2};
  const Point pa{0.0, 0.0}, qa = pa + std::polar(1.0, 0.3), pc{4.0, 1.0};
  const Point f = (pc - std::exp(L) * pa) / (1.0 - std::exp(L));
  for (const double t : {0.5, 0.6, 1.1, 1.5, 2.45, 2.5, 3.0}) {
    SCOPED_TRACE(t);
    const FrameDerivatives d = frame_derivatives(motion, t);
    const Complex e = std::exp(L * (t - 0.5) / 2.0), rate = L / 2.0;
    EXPECT_LT(relative(d.p, f + e * (pa - f)), 1e-12);
    EXPECT_LT(relative(d.dp, rate * e * (pa - f)), 1e-8);
    EXPECT_LT(relative(d.dq, rate * e * (qa - f)), 1e-8);
    EXPECT_LT(relative(d.ddp, rate * rate * e * (pa - f)), 1e-7);
    EXPECT_LT(relative(d.ddq, rate * rate * e * (qa - f)), 1e-7);
    // A steady morph turns about f: both centers are f at every t.
    ASSERT_TRUE(velocity_center(d) && acceleration_center(d));
    EXPECT_LT(std::abs(*velocity_center(d) - f), 1e-7);
    EXPECT_LT(std::abs(*acceleration_center(d) - f), 1e-6);
  }
}

TEST(FrameDerivatives, P1AccelerationIsConstantAndTheParabolas) {
  // P1 moves p and q on the Lagrange parabolas through the keyframes (PITA Eq. 11):
  // the acceleration is twice the second divided difference, at every t,
  // also at and between uneven knots and outside them.
  const motion::SceneMotion motion = motion_of("P1", kUneven);
  const double a = 0.0, b = 1.3, c = 2.0;
  const Point pa{0.0, 0.0}, pb{3.0, 1.5}, pc{6.0, -0.5};
  const Point qa = pa + std::polar(1.0, 0.4), qb = pb + std::polar(0.7, 1.5), qc = pc + std::polar(1.4, 2.2);
  const auto second = [&](Point xa, Point xb, Point xc) {
    return 2.0 * ((xc - xb) / (c - b) - (xb - xa) / (b - a)) / (c - a);
  };
  const auto first = [&](Point xa, Point xb, Point xc, double t) {  // derivative of the Lagrange parabola
    return xa * ((t - b) + (t - c)) / ((a - b) * (a - c)) + xb * ((t - a) + (t - c)) / ((b - a) * (b - c)) +
           xc * ((t - a) + (t - b)) / ((c - a) * (c - b));
  };
  for (const double t : {-0.4, 0.0, 0.01, 0.7, 1.3, 1.31, 1.99, 2.0, 2.6}) {
    SCOPED_TRACE(t);
    const FrameDerivatives d = frame_derivatives(motion, t);
    EXPECT_LT(relative(d.ddp, second(pa, pb, pc)), 1e-8);
    EXPECT_LT(relative(d.ddq, second(qa, qb, qc)), 1e-8);
    EXPECT_LT(relative(d.dp, first(pa, pb, pc, t)), 1e-9);
    EXPECT_LT(relative(d.dq, first(qa, qb, qc, t)), 1e-9);
  }
}

TEST(FrameDerivatives, P7IsRadiallyPerseverant) {
  // PITA Eq. 35: x'' = S (x - f) for p and q, one S for all t, f P7's global fixed
  // point. With knots 0, 1/2, 1, tau = 2t - 1, so S = 4 k^2 with cosh k =
  // (v_a + v_c)/(2 v_b) (reading note 13), computed here from the keyframes.
  const motion::SceneMotion motion = motion_of("P7", kEven);
  const std::optional<Point> f = motion.arrows().global_fixed_point();
  ASSERT_TRUE(f);
  const Vector va = std::polar(1.2, 0.9), vb = std::polar(0.6, 2.6), vc = std::polar(1.5, 4.0);
  const Complex k = std::acosh((va + vc) / (2.0 * vb));
  const Complex S = 4.0 * k * k;
  for (int i = 0; i <= 12; ++i) {
    const double t = i / 12.0;
    SCOPED_TRACE(t);
    const FrameDerivatives d = frame_derivatives(motion, t);
    EXPECT_LT(relative(d.ddp / (d.p - *f), S), 1e-7);
    EXPECT_LT(relative(d.ddq / (d.q - *f), S), 1e-7);
    // The acceleration center of P7 is its global fixed point.
    ASSERT_TRUE(acceleration_center(d));
    EXPECT_LT(std::abs(*acceleration_center(d) - *f) / std::abs(*f), 1e-7);
  }
}

TEST(FrameDerivatives, P8IsLocallyPerseverant) {
  // PITA Eq. 39: the accelerations of p and q are constant in the moving frame:
  // x''/v with v = q - p does not depend on t. The vector's own v''/v is the
  // same 4 k^2 as P7's, and x'' = 4 k^2 (x - c_a(t)) about the acceleration center.
  const motion::SceneMotion motion = motion_of("P8", kEven);
  const Vector va = std::polar(1.2, 0.9), vb = std::polar(0.6, 2.6), vc = std::polar(1.5, 4.0);
  const Complex k = std::acosh((va + vc) / (2.0 * vb));
  const Complex e = 4.0 * k * k;
  const FrameDerivatives d0 = frame_derivatives(motion, 0.0);
  const Complex local_p = d0.ddp / (d0.q - d0.p), local_q = d0.ddq / (d0.q - d0.p);
  for (int i = 1; i <= 12; ++i) {
    const double t = i / 12.0;
    SCOPED_TRACE(t);
    const FrameDerivatives d = frame_derivatives(motion, t);
    const Vector v = d.q - d.p;
    EXPECT_LT(relative(d.ddp / v, local_p), 1e-7);
    EXPECT_LT(relative(d.ddq / v, local_q), 1e-7);
    EXPECT_LT(relative((d.ddq - d.ddp) / v, e), 1e-7);
    const std::optional<Point> c = acceleration_center(d);
    ASSERT_TRUE(c);
    EXPECT_LT(relative(d.ddp / (d.p - *c), e), 1e-7);
  }
}

// The point of local coordinate z = (x - p)/v at time t, carried to time s.
Point carried(const motion::SceneMotion& motion, Point x, const FrameDerivatives& at, double s) {
  const Complex z = (x - at.p) / (at.q - at.p);
  const Arrow frame = motion.arrow_at(s);
  return frame.p + z * (frame.q() - frame.p);
}

TEST(FrameDerivatives, CentersAreAtRestByAnIndependentDifference) {
  // The velocity center does not move at t, the acceleration center does not
  // accelerate: second-order differences of D with small steps, unlike the
  // stencils under test.
  for (const std::string method : {"P2", "P6", "P8", "P5"}) {
    const motion::SceneMotion motion = motion_of(method, kEven);
    for (const double t : {0.13, 0.37, 0.8}) {
      SCOPED_TRACE(method + " t = " + std::to_string(t));
      const FrameDerivatives d = frame_derivatives(motion, t);
      const std::optional<Point> cv = velocity_center(d), ca = acceleration_center(d);
      ASSERT_TRUE(cv && ca);
      const double h = 1e-5, g = 1e-3;
      const Vector velocity = (carried(motion, *cv, d, t + h) - carried(motion, *cv, d, t - h)) / (2.0 * h);
      const Vector acceleration =
          (carried(motion, *ca, d, t + g) - 2.0 * *ca + carried(motion, *ca, d, t - g)) / (g * g);
      EXPECT_LT(std::abs(velocity), 1e-6 * std::abs(d.dp)) << std::abs(d.dp);
      EXPECT_LT(std::abs(acceleration), 1e-4 * std::abs(d.ddp)) << std::abs(d.ddp);
      // Elsewhere the plane does move: p itself has the velocity d.dp.
      const Vector of_p = (carried(motion, d.p, d, t + h) - carried(motion, d.p, d, t - h)) / (2.0 * h);
      EXPECT_LT(std::abs(of_p - d.dp), 1e-6 * std::abs(d.dp));
    }
  }
}

}  // namespace
}  // namespace pita::analysis
