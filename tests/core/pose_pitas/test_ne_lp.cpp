// PoseNeLp (src/core/pose_pitas/ne_lp.cpp, docs/paper-notes.md N76): interpolation, the
// independent oracle, the arrow PoseNeLp on similarity poses, the invariances and
// the refusals.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "core/neville_ratios.hpp"
#include "core/pitas/p09_ne_lp.hpp"
#include "core/pose_pitas/ne_lp.hpp"
#include "core/steady_morph.hpp"
#include "pose_pita_checks.hpp"

namespace pita {
namespace {

TEST(PoseNeLp, InterpolatesInThePlane) { test::expect_interpolates<PoseNeLp, 2>(1); }
TEST(PoseNeLp, InterpolatesInSpace) { test::expect_interpolates<PoseNeLp, 3>(2); }

TEST(PoseNeLp, MatchesMatrixFunctionsInThePlane) {
  EXPECT_GE((test::expect_matches_oracle<PoseNeLp, 2>(test::oracle_p9<2>, 3, test::kShapeOf<PoseNeLp>)), 150);
  EXPECT_GE((test::expect_matches_oracle<PoseNeLp, 2>(test::oracle_p9<2>, 4, test::wider(test::kShapeOf<PoseNeLp>))),
            120);
}
TEST(PoseNeLp, MatchesMatrixFunctionsInSpace) {
  EXPECT_GE((test::expect_matches_oracle<PoseNeLp, 3>(test::oracle_p9<3>, 5, test::kShapeOf<PoseNeLp>)), 150);
  EXPECT_GE((test::expect_matches_oracle<PoseNeLp, 3>(test::oracle_p9<3>, 6, test::wider(test::kShapeOf<PoseNeLp>))),
            120);
}

TEST(PoseNeLp, IsTheArrowPitaOnSimilarities) {
  const auto arrows = [](const KeyframeTriple& k) -> std::unique_ptr<Motion> { return std::make_unique<NeLp>(k); };
  // The arrow P9 turns from M(A, B, q) to M(B, C, r) by their winding
  // difference, the pose P9 by its principal angle: they agree where that
  // difference is below pi (docs/paper-notes.md N76).
  const auto comparable = [](const KeyframeTriple& k, double t) {
    const NevilleRatios n = neville_ratios(k.a.t, k.b.t, k.c.t, t);
    const Arrow from = steady_morph(k.a.arrow, k.b.arrow, n.q), to = steady_morph(k.b.arrow, k.c.arrow, n.r);
    return std::abs(to.w - from.w) < 3.0;
  };
  test::expect_matches_arrows<PoseNeLp>(arrows, 7, false, comparable);
  test::expect_matches_arrows<PoseNeLp>(arrows, 8, true, comparable);
}

TEST(PoseNeLp, IsSymmetricAndAffineInvariantOnBothSides) {
  for (const int n : {2, 3}) {
    const auto measure = [&](bool left, bool right, bool translations) {
      return n == 2 ? test::invariance_departure<PoseNeLp, 2>(9, left, right, translations)
                    : test::invariance_departure<PoseNeLp, 3>(9, left, right, translations);
    };
    const double reversal =
        n == 2 ? test::reversal_departure<PoseNeLp, 2>(10) : test::reversal_departure<PoseNeLp, 3>(10);
    // Symmetric, and invariant to affinities on either side (docs/paper-notes.md N73).
    EXPECT_LT(reversal, 1e-12) << n;
    EXPECT_LT(measure(true, false, false), 1e-12) << n;
    EXPECT_LT(measure(false, true, false), 1e-12) << n;
    EXPECT_LT(measure(true, true, false), 1e-12) << n;
  }
}

const Affine2 kPoseNeLpNegative{Eigen::Matrix2d{{-2.0, 0.0}, {0.0, -0.5}}, Eigen::Vector2d(1.0, 0.0)};  // G3 from I

TEST(PoseNeLp, RefusesNeighboursWithoutSam) {
  const PoseTriple<Affine2> k{{{0.0, Affine2{}}, {0.5, kPoseNeLpNegative}, {1.0, Affine2{}}}};
  EXPECT_THROW(PoseNeLp<Affine2>{k}, NoSamBetweenPoses);
}

TEST(PoseNeLp, RefusesAtTheTimeAPowerIsMissing) {
  for (const int n : test::wild_dimensions()) {
    const test::Refusals seen = n == 2 ? test::refusals_in_wild_triples<PoseNeLp, 2>(test::oracle_p9<2>, 15)
                                       : test::refusals_in_wild_triples<PoseNeLp, 3>(test::oracle_p9<3>, 16);
    EXPECT_GT(seen.refused, test::sample_size(10, 1)) << n;
    EXPECT_EQ(seen.disagreed, 0) << n;
    EXPECT_GT(seen.frames, test::sample_size(3000, 600)) << n;
  }
}

}  // namespace
}  // namespace pita
