// Shared helpers of the chain tests: random keyframe tracks (uneven knots,
// wild magnitudes, large windings) and one-sided derivatives by finite
// differences, to check interpolation and C1 at the knots independently of
// how the chains are built.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"
#include "core/steady_morph.hpp"
#include "core/twirl.hpp"

namespace pita::test {

struct TrackSampler {
  explicit TrackSampler(std::uint64_t seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

  // n keyframes; knot gaps over a factor e^3, windings drifting by up to
  // `turn_drift` radians per keyframe (several turns when wild), magnitudes
  // over e^{+-magnitude_spread}.
  std::vector<Keyframe> track(int n, double turn_drift = 3.0, double magnitude_spread = 0.7, double knot_spread = 1.5) {
    std::vector<Keyframe> keys;
    double t = uniform(-2.0, 2.0);
    double w = uniform(-3.0, 3.0);
    for (int i = 0; i < n; ++i) {
      if (i > 0) {
        t += std::exp(uniform(-knot_spread, knot_spread));
        w += uniform(-turn_drift, turn_drift);
      }
      keys.push_back(
          {t,
           Arrow{{uniform(-5.0, 5.0), uniform(-5.0, 5.0)}, std::exp(uniform(-magnitude_spread, magnitude_spread)), w}});
    }
    return keys;
  }
  std::mt19937_64 rng;
};

// The size of a track: distances are compared to it.
inline double extent(const std::vector<Keyframe>& keys) {
  double e = 0.0;
  for (const Keyframe& k : keys) e = std::max({e, std::abs(k.arrow.p), std::abs(k.arrow.q()), k.arrow.m});
  return e;
}

// Second-order one-sided derivatives of p and q at t, from the left (side
// -1) or the right (+1): (-3 f(t) + 4 f(t + s h) - f(t + 2 s h)) / (2 s h).
struct Slopes {
  Complex p, q;
};
inline Slopes one_sided(const Motion& motion, double t, double h, int side) {
  const double step = side * h;
  const Arrow a = motion.at(t), b = motion.at(t + step), c = motion.at(t + 2.0 * step);
  const auto d = [step](Complex f0, Complex f1, Complex f2) { return (-3.0 * f0 + 4.0 * f1 - f2) / (2.0 * step); };
  return {d(a.p, b.p, c.p), d(a.q(), b.q(), c.q())};
}

// The jump of the velocity of p and q at t, relative to the larger speed
// (or to `scale`, a speed the track makes natural, when that is larger).
inline double velocity_jump(const Motion& motion, double t, double h, double scale) {
  const Slopes left = one_sided(motion, t, h, -1), right = one_sided(motion, t, h, +1);
  const double speed = std::max({std::abs(left.p), std::abs(left.q), std::abs(right.p), std::abs(right.q), scale});
  return std::max(std::abs(left.p - right.p), std::abs(left.q - right.q)) / speed;
}

// The test's own steady blend of two frames: PITA Eq. 20, with Y's winding first
// taken on the branch nearest X's for a method whose windings count only
// modulo 2 pi (written out here, not taken from core/chains).
inline Arrow blend_of(const Arrow& X, Arrow Y, double s, bool winding_aware) {
  if (!winding_aware) Y.w = X.w + principal_angle(Y.w - X.w);
  return steady_morph(X, Y, s);
}

// Keyframes moved by the similarity S (PITA Eq. 40).
inline std::vector<Keyframe> moved(const Twirl& S, const std::vector<Keyframe>& keys) {
  std::vector<Keyframe> out;
  for (const Keyframe& k : keys) out.push_back({k.t, S * k.arrow});
  return out;
}

}  // namespace pita::test
