// The carrier similarity of Sec. 7.1 (core/carrier.hpp): (X, E) ~ (X_t, D(t)).
#include <cmath>

#include <gtest/gtest.h>

#include "core/carrier.hpp"
#include "core/methods.hpp"
#include "test_support.hpp"

namespace pita {
namespace {

using test::Config;
using test::Sampler;

double distance(Point a, Point b) { return std::abs(a - b); }

TEST(Carrier, TakesTheHandleOntoTheFrame) {
  Sampler sampler(11);
  for (int i = 0; i < 200; ++i) {
    const Arrow handle = sampler.arrow(Config::wild);
    const Arrow frame = sampler.arrow(Config::wild);
    const Affine2 S = carrier(handle, frame);
    const double scale = std::max({1.0, std::abs(frame.p), frame.m});
    EXPECT_LT(distance(apply(S, handle.p), frame.p), 1e-12 * scale * std::max(1.0, std::abs(handle.p) / handle.m));
    EXPECT_LT(distance(apply(S, handle.q()), frame.q()),
              1e-12 * scale * std::max(1.0, std::abs(handle.q()) / handle.m));
  }
}

TEST(Carrier, IsADirectSimilarity) {
  // L = s R(theta): equal diagonal, opposite off-diagonal, positive determinant,
  // scale |D| / |E| and angle w_D - w_E (mod 2 pi).
  Sampler sampler(12);
  for (int i = 0; i < 100; ++i) {
    const Arrow handle = sampler.arrow(Config::tame);
    const Arrow frame = sampler.arrow(Config::tame);
    const Affine2 S = carrier(handle, frame);
    EXPECT_NEAR(S.L(0, 0), S.L(1, 1), 1e-12);
    EXPECT_NEAR(S.L(0, 1), -S.L(1, 0), 1e-12);
    EXPECT_GT(S.L.determinant(), 0.0);
    EXPECT_NEAR(std::sqrt(S.L.determinant()), frame.m / handle.m, 1e-12);
    const double angle = std::atan2(S.L(1, 0), S.L(0, 0));
    EXPECT_NEAR(std::remainder(angle - (frame.w - handle.w), 2.0 * test::kPi), 0.0, 1e-12);
  }
}

TEST(Carrier, OfTheHandleItselfIsTheIdentity) {
  const Arrow handle{{1.5, -2.0}, 0.7, 2.9};
  const Affine2 S = carrier(handle, handle);
  EXPECT_TRUE(S.L.isApprox(Eigen::Matrix2d::Identity(), 1e-14));
  EXPECT_LT(S.b.norm(), 1e-14);
}

// Fig. 23 (b): another handle E2 over the same picture, with keyframes that
// put the picture where E1's keyframes put it (K2_i = S_i(E2), S_i the
// carrier of K1_i), gives the same animation of the picture exactly for the
// handle-invariant PITAs (Fig. 10 row H: P1, P4, P6, P7, P8), and another
// one for P2 and P3 (Sec. 4.5).
TEST(Carrier, AnotherHandleGivesTheSameAnimationForHandleInvariantPitas) {
  const Arrow e1{{6.3, 3.25}, 1.0, 0.0};
  const Arrow e2 = zero_turn_arrow({6.05, 3.05}, {7.28, 3.96});
  const KeyframeTriple k1{
      {0.0, {{0.0, 0.0}, 1.3, 0.35}}, {1.0, {{3.2, 1.6}, 1.0, 1.4}}, {2.0, {{6.2, -0.8}, 1.5, -0.3}}};
  const auto moved = [&](const Keyframe& key) {
    const Affine2 S = carrier(e1, key.arrow);
    Arrow a = zero_turn_arrow(apply(S, e2.p), apply(S, e2.q()));
    // the same turns as the keyframe (the handle's own turn is e2.w - e1.w)
    a.w = key.arrow.w + (e2.w - e1.w);
    return Keyframe{key.t, a};
  };
  const KeyframeTriple k2{moved(k1.a), moved(k1.b), moved(k1.c)};
  const auto worst = [&](Method m) {
    const auto d1 = test::motion(m, k1);
    const auto d2 = test::motion(m, k2);
    double d = 0.0;
    for (double t = -0.2; t <= 2.2; t += 0.05) {
      const Affine2 s1 = carrier(e1, d1->at(t)), s2 = carrier(e2, d2->at(t));
      // the picture's corners under both
      for (const Point x : {Point{6.0, 3.0}, Point{7.6, 3.0}, Point{7.6, 4.2}, Point{6.0, 4.2}}) {
        d = std::max(d, distance(apply(s1, x), apply(s2, x)));
      }
    }
    return d;
  };
  for (const Method m : {Method::P1, Method::P4, Method::P6, Method::P7, Method::P8}) {
    EXPECT_LT(worst(m), 1e-9) << info(m).id;
  }
  for (const Method m : {Method::P2, Method::P3}) {
    EXPECT_GT(worst(m), 1e-3) << info(m).id << " is not handle-invariant (Sec. 4.5)";
  }
}

}  // namespace
}  // namespace pita
