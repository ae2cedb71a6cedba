// PoseHeLp (src/core/pose_pitas/he_lp.cpp, docs/paper-notes.md N78): interpolation, the
// independent oracle, the arrow PoseHeLp on similarity poses, the invariances and
// the refusals.
#include <memory>

#include <gtest/gtest.h>

#include "core/pitas/p05_he_lp.hpp"
#include "core/pose_pitas/he_lp.hpp"
#include "pose_pita_checks.hpp"

namespace pita {
namespace test {
// P5 takes each pose's own log: poses that turn by at most 0.7 + 2 x 1 rad.
template <>
inline const Shape kShapeOf<PoseHeLp>{0.7, 1.0, 0.25, false};
}  // namespace test

namespace {

TEST(PoseHeLp, InterpolatesInThePlane) { test::expect_interpolates<PoseHeLp, 2>(1); }
TEST(PoseHeLp, InterpolatesInSpace) { test::expect_interpolates<PoseHeLp, 3>(2); }

TEST(PoseHeLp, MatchesMatrixFunctionsInThePlane) {
  EXPECT_GE((test::expect_matches_oracle<PoseHeLp, 2>(test::oracle_p5<2>, 3, test::kShapeOf<PoseHeLp>)), 150);
  EXPECT_GE((test::expect_matches_oracle<PoseHeLp, 2>(test::oracle_p5<2>, 4, test::wider(test::kShapeOf<PoseHeLp>))),
            120);
}
TEST(PoseHeLp, MatchesMatrixFunctionsInSpace) {
  EXPECT_GE((test::expect_matches_oracle<PoseHeLp, 3>(test::oracle_p5<3>, 5, test::kShapeOf<PoseHeLp>)), 150);
  EXPECT_GE((test::expect_matches_oracle<PoseHeLp, 3>(test::oracle_p5<3>, 6, test::wider(test::kShapeOf<PoseHeLp>))),
            120);
}

TEST(PoseHeLp, IsTheArrowPitaOnSimilarities) {
  const auto arrows = [](const KeyframeTriple& k) -> std::unique_ptr<Motion> {
    return std::make_unique<HeLp>(k, HomogeneousCenter::centroid);
  };
  test::expect_matches_arrows<PoseHeLp>(arrows, 7);
  test::expect_matches_arrows<PoseHeLp>(arrows, 8, true);
}

TEST(PoseHeLp, IsSymmetricAndInvariantToLeftTranslationsOnly) {
  for (const int n : {2, 3}) {
    const auto measure = [&](bool left, bool right, bool translations) {
      return n == 2 ? test::invariance_departure<PoseHeLp, 2>(9, left, right, translations)
                    : test::invariance_departure<PoseHeLp, 3>(9, left, right, translations);
    };
    const double reversal =
        n == 2 ? test::reversal_departure<PoseHeLp, 2>(10) : test::reversal_departure<PoseHeLp, 3>(10);
    // Symmetric and invariant to left translations only (docs/paper-notes.md N78).
    EXPECT_LT(reversal, 1e-12) << n;
    EXPECT_LT(measure(true, false, true), 1e-12) << n;
    EXPECT_GT(measure(true, false, false), 1e-2) << n;
    EXPECT_GT(measure(false, true, false), 1e-2) << n;
    EXPECT_GT(measure(false, true, true), 1e-2) << n;
  }
}

const Affine2 kPoseHeLpNegative{Eigen::Matrix2d{{-2.0, 0.0}, {0.0, -0.5}}, Eigen::Vector2d(1.0, 0.0)};  // G3 from I

TEST(PoseHeLp, RefusesNeighboursWithoutSam) {
  const PoseTriple<Affine2> k{{{0.0, Affine2{}}, {0.5, kPoseHeLpNegative}, {1.0, Affine2{}}}};
  EXPECT_THROW(PoseHeLp<Affine2>{k}, NoSamBetweenPoses);
}

TEST(PoseHeLp, RefusesAtTheTimeAPowerIsMissing) {
  for (const int n : test::wild_dimensions()) {
    const test::Refusals seen = n == 2 ? test::refusals_in_wild_triples<PoseHeLp, 2>(test::oracle_p5<2>, 15)
                                       : test::refusals_in_wild_triples<PoseHeLp, 3>(test::oracle_p5<3>, 16);
    EXPECT_EQ(seen.refused, 0) << n;  // P5 has no power that depends on time
    EXPECT_EQ(seen.disagreed, 0) << n;
    EXPECT_GT(seen.frames, test::sample_size(3000, 600)) << n;
  }
}

}  // namespace
}  // namespace pita
