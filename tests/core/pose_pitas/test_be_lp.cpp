// PoseBeLp (src/core/pose_pitas/be_lp.cpp, docs/paper-notes.md N77): interpolation, the
// independent oracle, the arrow PoseBeLp on similarity poses, the invariances and
// the refusals.
#include <memory>

#include <gtest/gtest.h>

#include "core/pitas/p04_be_lp.hpp"
#include "core/pose_pitas/be_lp.hpp"
#include "pose_pita_checks.hpp"

namespace pita {
namespace {

TEST(PoseBeLp, InterpolatesInThePlane) { test::expect_interpolates<PoseBeLp, 2>(1); }
TEST(PoseBeLp, InterpolatesInSpace) { test::expect_interpolates<PoseBeLp, 3>(2); }

TEST(PoseBeLp, MatchesMatrixFunctionsInThePlane) {
  EXPECT_GE((test::expect_matches_oracle<PoseBeLp, 2>(test::oracle_p4<2>, 3, test::kShapeOf<PoseBeLp>)), 150);
  EXPECT_GE((test::expect_matches_oracle<PoseBeLp, 2>(test::oracle_p4<2>, 4, test::wider(test::kShapeOf<PoseBeLp>))),
            120);
}
TEST(PoseBeLp, MatchesMatrixFunctionsInSpace) {
  EXPECT_GE((test::expect_matches_oracle<PoseBeLp, 3>(test::oracle_p4<3>, 5, test::kShapeOf<PoseBeLp>)), 150);
  EXPECT_GE((test::expect_matches_oracle<PoseBeLp, 3>(test::oracle_p4<3>, 6, test::wider(test::kShapeOf<PoseBeLp>))),
            120);
}

TEST(PoseBeLp, IsTheArrowPitaOnSimilarities) {
  const auto arrows = [](const KeyframeTriple& k) -> std::unique_ptr<Motion> { return std::make_unique<BeLp>(k); };
  test::expect_matches_arrows<PoseBeLp>(arrows, 7);
  test::expect_matches_arrows<PoseBeLp>(arrows, 8, true);
}

TEST(PoseBeLp, IsSymmetricAndAffineInvariantOnBothSides) {
  for (const int n : {2, 3}) {
    const auto measure = [&](bool left, bool right, bool translations) {
      return n == 2 ? test::invariance_departure<PoseBeLp, 2>(9, left, right, translations)
                    : test::invariance_departure<PoseBeLp, 3>(9, left, right, translations);
    };
    const double reversal =
        n == 2 ? test::reversal_departure<PoseBeLp, 2>(10) : test::reversal_departure<PoseBeLp, 3>(10);
    // Symmetric, and invariant to affinities on either side (docs/paper-notes.md N73).
    EXPECT_LT(reversal, 1e-12) << n;
    EXPECT_LT(measure(true, false, false), 1e-12) << n;
    EXPECT_LT(measure(false, true, false), 1e-12) << n;
    EXPECT_LT(measure(true, true, false), 1e-12) << n;
  }
}

const Affine2 kPoseBeLpNegative{Eigen::Matrix2d{{-2.0, 0.0}, {0.0, -0.5}}, Eigen::Vector2d(1.0, 0.0)};  // G3 from I

TEST(PoseBeLp, RefusesNeighboursWithoutSam) {
  const PoseTriple<Affine2> k{{{0.0, Affine2{}}, {0.5, kPoseBeLpNegative}, {1.0, Affine2{}}}};
  EXPECT_THROW(PoseBeLp<Affine2>{k}, NoSamBetweenPoses);
}

TEST(PoseBeLp, RefusesAtTheTimeAPowerIsMissing) {
  for (const int n : test::wild_dimensions()) {
    const test::Refusals seen = n == 2 ? test::refusals_in_wild_triples<PoseBeLp, 2>(test::oracle_p4<2>, 15)
                                       : test::refusals_in_wild_triples<PoseBeLp, 3>(test::oracle_p4<3>, 16);
    EXPECT_GT(seen.refused, test::sample_size(10, 1)) << n;
    EXPECT_EQ(seen.disagreed, 0) << n;
    EXPECT_GT(seen.frames, test::sample_size(3000, 600)) << n;
  }
}

}  // namespace
}  // namespace pita
