// The independent combinations of Fig. 7 (Sec. 3.1): the point motion and the
// vector motion are chosen separately, so each combination must take its
// point from one basket PITA and its vector from another: Pa- from P1, LS-
// from P2 (anchored at the start), -Ca from P1, -Po from P2, -LP from P3.
// Also interpolation, symmetry (PITA Eq. 41) and similarity invariance (PITA Eq. 40).
#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace pita::test {
namespace {

struct Combination {
  Method method;
  Method point_from;
  Method vector_from;
};

const Combination kCombinations[] = {
    {Method::PaPo, Method::P1, Method::P2},
    {Method::LSCa, Method::P2, Method::P1},
    {Method::LSLP, Method::P2, Method::P3},
};

TEST(Independent, TakesPointAndVectorFromTheirParents) {
  Sampler s(71);
  for (const Combination& c : kCombinations) {
    for (int i = 0; i < 100; ++i) {
      const KeyframeTriple k = s.triple(i % 2 ? Config::uneven : Config::tame);
      const auto D = motion(c.method, k), P = motion(c.point_from, k), V = motion(c.vector_from, k);
      for (double t : sample_times(k)) {
        const Arrow d = D->at(t), p = P->at(t), v = V->at(t);
        EXPECT_NEAR(std::abs(d.p - p.p), 0.0, 1e-12 * (1 + extent(k))) << name(c.method);
        EXPECT_NEAR(std::abs(d.vector() - v.vector()), 0.0, 1e-12 * (1 + extent(k))) << name(c.method);
        if (c.vector_from != Method::P1) {
          EXPECT_NEAR(d.w, v.w, 1e-12 * (1 + std::abs(v.w)));
        }
      }
    }
  }
}

TEST(Independent, InterpolatesIsSymmetricAndSimilarityInvariant) {
  Sampler s(72);
  for (const Combination& c : kCombinations) {
    for (int i = 0; i < 100; ++i) {
      const KeyframeTriple k = s.triple(Config::uneven);
      const auto D = motion(c.method, k);
      const bool aware = info(c.method).winding_aware;
      EXPECT_TRUE(arrows_near(D->at(k.a.t), k.a.arrow, 1e-9, extent(k), !aware)) << name(c.method);
      EXPECT_TRUE(arrows_near(D->at(k.b.t), k.b.arrow, 1e-9, extent(k), !aware)) << name(c.method);
      EXPECT_TRUE(arrows_near(D->at(k.c.t), k.c.arrow, 1e-9, extent(k), !aware)) << name(c.method);
      // PITA Eq. 41: reversing time and keyframes gives the same frames.
      const KeyframeTriple reversed{{-k.c.t, k.c.arrow}, {-k.b.t, k.b.arrow}, {-k.a.t, k.a.arrow}};
      const auto R = motion(c.method, reversed);
      // PITA Eq. 40: a similarity of the keyframes moves every frame the same way.
      const Twirl S = twirl({0.3, -1.2}, 1.7, 0.9);
      const auto DS = motion(c.method, transformed(S, k));
      for (double t : sample_times(k)) {
        EXPECT_TRUE(arrows_near(R->at(-t), D->at(t), 1e-9, extent(k), !aware)) << name(c.method);
        EXPECT_TRUE(arrows_near(DS->at(t), S * D->at(t), 1e-9, 1.7 * extent(k), !aware)) << name(c.method);
      }
    }
  }
}

}  // namespace
}  // namespace pita::test
