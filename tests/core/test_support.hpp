// Shared helpers of the core tests: seeded random configurations, the
// similarity action on keyframes, and comparisons that say which field of
// which frame differs and by how much (libigl's tests/test_common.h habit).
#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/arrow.hpp"
#include "core/keyframe.hpp"
#include "core/pitas/registry.hpp"
#include "core/twirl.hpp"

namespace pita::test {

inline constexpr double kPi = std::numbers::pi;

// Kinds of random configurations the property suites run over.
enum class Config {
  tame,    // magnitudes within e^{+-0.7}, windings in (-pi, pi], even knots
  uneven,  // tame arrows, middle knot anywhere in [0.2, 0.8]
  wild,    // magnitudes over 1e-2..1e2 and windings up to +-20 (several turns)
};

struct Sampler {
  explicit Sampler(std::uint64_t seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Point point(double r = 5.0) { return {uniform(-r, r), uniform(-r, r)}; }
  Arrow arrow(Config c) {
    if (c == Config::wild) return {point(), std::exp(uniform(-4.6, 4.6)), uniform(-20.0, 20.0)};
    return {point(), std::exp(uniform(-0.7, 0.7)), uniform(-kPi, kPi)};
  }
  KeyframeTriple triple(Config c) {
    const double a = uniform(-2.0, 2.0);
    const double span = std::exp(uniform(-1.0, 1.0));
    const double beta = c == Config::uneven ? uniform(0.2, 0.8) : 0.5;
    return {{a, arrow(c)}, {a + beta * span, arrow(c)}, {a + span, arrow(c)}};
  }
  std::mt19937_64 rng;
};

// The size of a configuration: distances between points are compared to it.
inline double extent(const KeyframeTriple& k) {
  double e = 0.0;
  for (const Keyframe* x : {&k.a, &k.b, &k.c}) {
    e = std::max({e, std::abs(x->arrow.p - k.b.arrow.p), std::abs(x->arrow.q() - k.b.arrow.p), x->arrow.m});
  }
  return e;
}

// Sample times: the knots, points in between, and a little extrapolation.
inline std::vector<double> sample_times(const KeyframeTriple& k, int n = 13, double beyond = 0.25) {
  std::vector<double> ts;
  const double a = k.a.t, c = k.c.t;
  for (int i = 0; i < n; ++i) {
    const double u = -beyond + (1.0 + 2.0 * beyond) * i / (n - 1);
    ts.push_back(a + (c - a) * u);
  }
  ts.push_back(k.b.t);
  return ts;
}

inline std::unique_ptr<Motion> motion(Method m, const KeyframeTriple& k, const MethodOptions& o = {}) {
  return make_pita(m, k, o);
}

// A twirl used as a similarity acting on whole keyframe sets (PITA Eq. 40).
inline KeyframeTriple transformed(const Twirl& S, const KeyframeTriple& k) {
  return {{k.a.t, S * k.a.arrow}, {k.b.t, S * k.b.arrow}, {k.c.t, S * k.c.arrow}};
}

// Difference of two arrows as frames: the largest of |dp| and |dq|.
inline double frame_distance(const Arrow& x, const Arrow& y) {
  return std::max(std::abs(x.p - y.p), std::abs(x.q() - y.q()));
}

// Winding difference; modulo 2 pi when `modulo_turns`.
inline double winding_distance(double w1, double w2, bool modulo_turns) {
  const double d = w1 - w2;
  return modulo_turns ? std::abs(principal_angle(d)) : std::abs(d);
}

// Checks that two arrows agree: p and q within tol * scale, m relatively, and
// w exactly or modulo 2 pi. Reports the field and the size of the difference.
inline ::testing::AssertionResult arrows_near(const Arrow& actual, const Arrow& expected, double tol, double scale,
                                              bool winding_modulo) {
  const double dp = std::abs(actual.p - expected.p) / scale;
  const double dq = std::abs(actual.q() - expected.q()) / scale;
  const double dm = std::abs(actual.m - expected.m) / std::max(std::abs(expected.m), 1e-300);
  const double dw = winding_distance(actual.w, expected.w, winding_modulo);
  std::string what;
  if (!(dp <= tol)) what += " p off by " + std::to_string(dp);
  if (!(dq <= tol)) what += " q off by " + std::to_string(dq);
  if (!(dm <= tol)) what += " m off by " + std::to_string(dm) + " (relative)";
  if (!(dw <= tol * 10.0)) what += " w off by " + std::to_string(dw);
  if (what.empty()) return ::testing::AssertionSuccess();
  char buf[256];
  std::snprintf(buf, sizeof buf, " [actual p=(%.12g,%.12g) m=%.12g w=%.12g; expected p=(%.12g,%.12g) m=%.12g w=%.12g]",
                actual.p.real(), actual.p.imag(), actual.m, actual.w, expected.p.real(), expected.p.imag(), expected.m,
                expected.w);
  return ::testing::AssertionFailure() << what << buf;
}

// The paper's PITAs (the methods of the basket that take three keyframes).
inline std::vector<Method> pitas() {
  std::vector<Method> out;
  for (const MethodInfo& m : all_methods()) {
    if (m.keyframe_count == 3 && m.in_basket) out.push_back(m.method);
  }
  return out;
}

inline std::string name(Method m) { return std::string(info(m).id); }

}  // namespace pita::test
