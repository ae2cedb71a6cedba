// The checks every pose PITA's test runs (tests/core/pose_pitas/test_*.cpp),
// one template over the construction Pita<Pose> and the dimension N:
// interpolation, the independent oracle (pose_pita_support.hpp), the arrow
// PITA of the same name on similarity poses, and the invariances measured
// (docs/paper-notes.md N73-N78 record what holds).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/affine2.hpp"
#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"
#include "pose_pita_support.hpp"
#include "support/sanitizers.hpp"

namespace pita::test {

// The shape of the random triples a construction is tested on (P5 needs each
// pose's own log: test_he_lp.cpp specializes it).
template <template <class> class Pita>
inline const Shape kShapeOf{};

// A shape with steps half as wide again, twice the stretch and even knots.
inline Shape wider(Shape shape) {
  shape.step_angle *= 1.5;
  shape.stretch *= 2.0;
  shape.even = true;
  return shape;
}

template <int N>
using Oracle = std::function<Affine<N>(const OracleTriple<N>&, double)>;

// D(a) = A, D(b) = B, D(c) = C on `count` random triples.
template <template <class> class Pita, int N>
void expect_interpolates(unsigned seed, int count = 20) {
  std::mt19937 rng(seed);
  for (int i = 0; i < count; ++i) {
    const PoseTriple<Affine<N>> k = random_triple<N>(rng, kShapeOf<Pita>);
    const Pita<Affine<N>> pita(k);
    for (const auto& key : k)
      EXPECT_LT(pose_distance(pita.at(key.t), key.pose), 1e-11) << "triple " << i << " t " << key.t;
  }
}

// The construction equals the oracle's at several times, on random triples
// Returns how many frames were compared (a refused frame is not).
template <template <class> class Pita, int N>
int expect_matches_oracle(const Oracle<N>& oracle, unsigned seed, const Shape& shape, int count = 30) {
  std::mt19937 rng(seed);
  int compared = 0;
  for (int i = 0; i < count; ++i) {
    const PoseTriple<Affine<N>> k = random_triple<N>(rng, shape);
    if (!neighbours_have_powers<N>(k)) continue;
    const Pita<Affine<N>> pita(k);
    const OracleTriple<N> o = oracle_of<N>(k);
    for (const double t : times_of(k)) {
      // Where the oracle finds no real power (NaN), the construction refuses.
      const Affine<N> expected = oracle(o, t);
      const bool oracle_refuses = !expected.L.allFinite();
      Affine<N> got;
      try {
        got = pita.at(t);
      } catch (const NoPosePitaPower&) {
        EXPECT_TRUE(oracle_refuses) << "triple " << i << " t " << t;
        continue;
      }
      EXPECT_FALSE(oracle_refuses) << "triple " << i << " t " << t;
      if (oracle_refuses) continue;
      const double scale = 1.0 + expected.L.norm() + expected.b.norm();
      EXPECT_LT(pose_distance(got, expected), 1e-9 * scale) << "triple " << i << " t " << t;
      ++compared;
    }
  }
  return compared;
}

// The largest distance between D(t) and D'(-t), D' the PITA of the reversed
// triple, at the sample times of `count` random triples.
template <template <class> class Pita, int N>
double reversal_departure(unsigned seed, int count = 20) {
  std::mt19937 rng(seed);
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    const PoseTriple<Affine<N>> k = random_triple<N>(rng, kShapeOf<Pita>);
    const Pita<Affine<N>> forward(k), backward(reversed<N>(k));
    for (const double t : times_of(k)) {
      try {
        worst = std::max(worst, pose_distance(forward.at(t), backward.at(-t)));
      } catch (const NoPosePitaPower&) {
        // a frame one of them refuses has nothing to compare
      }
    }
  }
  return worst;
}

// The largest distance between G o D(A, B, C) o H and D(G o A o H, ...), with
// G, H random affinities (steps of random_step) or, when `translations`, random
// translations only.
template <template <class> class Pita, int N>
double invariance_departure(unsigned seed, bool left, bool right, bool translations, int count = 20) {
  std::mt19937 rng(seed);
  double worst = 0.0;
  for (int i = 0; i < count; ++i) {
    const PoseTriple<Affine<N>> k = random_triple<N>(rng, kShapeOf<Pita>);
    Affine<N> G = random_step<N>(rng, 3.0, 0.4), H = random_step<N>(rng, 3.0, 0.4);
    if (translations) G.L = H.L = Affine<N>::Linear::Identity();
    if (!left) G = Affine<N>::identity();
    if (!right) H = Affine<N>::identity();
    try {
      const Pita<Affine<N>> plain(k), moved_pita(moved<N>(G, k, H));
      for (const double t : times_of(k)) {
        try {
          const Affine<N> expected = compose(G, compose(plain.at(t), H));
          const double scale = 1.0 + expected.L.norm() + expected.b.norm();
          worst = std::max(worst, pose_distance(moved_pita.at(t), expected) / scale);
        } catch (const NoPosePitaPower&) {
          // a refused frame has nothing to compare
        }
      }
    } catch (const NoPosePitaPower&) {
      // P5: a moved pose may have no log of its own
    }
  }
  return worst;
}

// Random arrows whose neighbours turn by less than pi (by at most 1.2 rad).
inline KeyframeTriple random_arrows(std::mt19937& rng, bool even) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), knot(0.25, 0.75);
  const auto arrow = [&](double w) { return Arrow{{3.0 * u(rng), 3.0 * u(rng)}, std::exp(0.7 * u(rng)), w}; };
  const Arrow A = arrow(3.0 * u(rng));
  const Arrow B = arrow(A.w + 1.2 * u(rng));
  const Arrow C = arrow(B.w + 1.2 * u(rng));
  return {{0.0, A}, {even ? 0.5 : knot(rng), B}, {1.0, C}};
}

// The similarity of an arrow in space: turning about the z axis.
inline Affine<3> affine3_of(const Arrow& arrow) {
  const Affine2 A = affine_of(arrow);
  Affine<3> S;
  S.L.topLeftCorner<2, 2>() = A.L;
  S.L(2, 2) = arrow.m;
  S.b << A.b, 0.0;
  return S;
}

// On similarity poses the pose PITA equals the arrow PITA on the matching
// arrows (x -> p + m R(w) x, affine_of), in the plane and embedded in space,
// at the times `comparable` allows (all when empty).
template <template <class> class Pita>
void expect_matches_arrows(const std::function<std::unique_ptr<Motion>(const KeyframeTriple&)>& arrow_pita,
                           unsigned seed, bool even = false,
                           const std::function<bool(const KeyframeTriple&, double)>& comparable = {}, int count = 30) {
  std::mt19937 rng(seed);
  for (int i = 0; i < count; ++i) {
    const KeyframeTriple k = random_arrows(rng, even);
    const std::unique_ptr<Motion> arrows = arrow_pita(k);
    const Pita<Affine2> plane(PoseTriple<Affine2>{
        {{k.a.t, affine_of(k.a.arrow)}, {k.b.t, affine_of(k.b.arrow)}, {k.c.t, affine_of(k.c.arrow)}}});
    const Pita<Affine<3>> space(PoseTriple<Affine<3>>{
        {{k.a.t, affine3_of(k.a.arrow)}, {k.b.t, affine3_of(k.b.arrow)}, {k.c.t, affine3_of(k.c.arrow)}}});
    for (const double t : {-0.2, 0.0, 0.2, k.b.t, 0.6, 0.9, 1.0, 1.2}) {
      if (comparable && !comparable(k, t)) continue;
      const Arrow expected = arrows->at(t);
      EXPECT_LT(pose_distance(plane.at(t), affine_of(expected)), 1e-9) << "triple " << i << " t " << t;
      EXPECT_LT(pose_distance(space.at(t), affine3_of(expected)), 1e-9) << "triple " << i << " t " << t;
    }
  }
}

// The dimensions the tests of wild triples run in: the plane and space, or
// under the sanitizers the plane only (space's code runs there in the other
// tests of the pose PITAs; these are the slowest of the suite under ASan).
inline std::vector<int> wild_dimensions() { return kUnderSanitizers ? std::vector<int>{2} : std::vector<int>{2, 3}; }

// What refusals_in_wild_triples saw.
struct Refusals {
  int frames = 0;     // frames sampled
  int refused = 0;    // frames refused at their time
  int disagreed = 0;  // frames where the oracle's finding differs
};

// Samples wild triples (steps up to 3.1 rad, strong stretch) at times in
// [a - 1, c + 1]: every frame is finite or refused (NoPosePitaPower naming its
// time), and, within half the span of the ends, is refused exactly where the
// oracle finds no real power.
template <template <class> class Pita, int N>
Refusals refusals_in_wild_triples(const Oracle<N>& oracle, unsigned seed, int count = sample_size(200, 60)) {
  std::mt19937 rng(seed);
  Refusals seen;
  for (int i = 0; i < count; ++i) {
    const PoseTriple<Affine<N>> k = random_triple<N>(rng, Shape{3.0, 3.1, 0.8, false});
    try {
      const Pita<Affine<N>> pita(k);
      const OracleTriple<N> o = oracle_of<N>(k);
      for (int j = 0; j <= 60; ++j) {
        const double t = -1.0 + j / 20.0;
        const bool oracle_refuses = !oracle(o, t).L.allFinite();
        bool refused = false;
        ++seen.frames;
        try {
          const Affine<N> d = pita.at(t);
          EXPECT_TRUE(d.L.allFinite() && d.b.allFinite()) << "triple " << i << " t " << t;
        } catch (const NoPosePitaPower& refusal) {
          refused = true;
          ++seen.refused;
          EXPECT_TRUE(refusal.time() && *refusal.time() == t) << refusal.where();
          EXPECT_NE(refusal.where().find("at t = "), std::string::npos) << refusal.where();
        }
        // Beyond half the span past the ends the extrapolated poses are so
        // ill-conditioned that the two eigenvalue tests may differ (N74).
        if (refused != oracle_refuses && t >= -0.5 && t <= 1.5) ++seen.disagreed;
      }
    } catch (const NoPosePitaPower& refusal) {
      EXPECT_FALSE(refusal.time().has_value()) << refusal.what();
    }
  }
  return seen;
}

}  // namespace pita::test
