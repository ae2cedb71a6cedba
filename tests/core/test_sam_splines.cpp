// Motions through several poses built from SAMs (core/sam_splines.hpp): the
// properties Sec. 5.3 and 7.3 of the SAM paper state for them.
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/pose_motion.hpp"
#include "core/sam_splines.hpp"
#include "pose_test_support.hpp"

namespace pita {
namespace {

using test::distance;
using test::pose;

using Eigen::Matrix2d;
using Eigen::Vector2d;

const Affine2& kA = test::kFig7A;
const Affine2& kB = test::kFig7B;
const Affine2& kC = test::kFig7C;

TEST(SamSplines, TheFigureSevenPairHasNoSam) {
  EXPECT_THROW(SteadyAffineMorph(kA, kC), NoRealLogarithm);
  EXPECT_NO_THROW(SteadyAffineMorph(kA, kB));
  EXPECT_NO_THROW(SteadyAffineMorph(kB, kC));
}

TEST(SamSplines, BiarcInterpolatesAndIsSmoothAtTheMiddlePose) {
  const SamBiarc biarc(kA, kB, kC);
  EXPECT_LT(distance(biarc.at(0.0), kA), 1e-12);
  EXPECT_LT(distance(biarc.at(0.5), kB), 1e-12);
  EXPECT_LT(distance(biarc.at(1.0), kC), 1e-12);
  // C1 at B: one-sided velocities agree (Sec. 5.3), unlike the polySAM's.
  const double h = 1e-6;
  const auto velocity_gap = [&](auto&& motion, double at) {
    const Affine2 before = motion(at - h), middle = motion(at), after = motion(at + h);
    const double gap =
        (after.L - middle.L - (middle.L - before.L)).norm() + (after.b - middle.b - (middle.b - before.b)).norm();
    return gap / h;
  };
  EXPECT_LT(velocity_gap([&](double u) { return biarc.at(u); }, 0.5), 1e-4);
  const PoseMotion poly(PoseMethod::poly_sam, {{0.0, kA}, {0.5, kB}, {1.0, kC}});
  EXPECT_GT(velocity_gap([&](double u) { return poly.at(u); }, 0.5), 0.5);
}

TEST(SamSplines, BezierOfPosesOnOneSamIsThatSam) {
  const Affine2 P = pose(1.0, 0.2, -0.1, 0.9, 0.0, 0.0), Q = pose(0.3, -1.2, 1.1, 0.4, 4.0, 1.0);
  const Affine2 middle = sam(P, 0.5, Q);
  for (const double t : {0.0, 0.2, 0.5, 0.8, 1.0}) {
    EXPECT_LT(distance(bezier_sam(P, middle, Q, t), sam(P, t, Q)), 1e-12) << t;
  }
  // Passes through its end poses, not through the middle control.
  EXPECT_LT(distance(bezier_sam(kA, kB, kC, 0.0), kA), 1e-15);
  EXPECT_LT(distance(bezier_sam(kA, kB, kC, 1.0), kC), 1e-12);
  EXPECT_GT(distance(bezier_sam(kA, kB, kC, 0.5), kB), 0.1);
}

TEST(SamSplines, SubdivisionKeepsARegularPatternRegular) {
  // P_i = M^i P_0: subdividing inserts M^{i + 1/2} P_0 (Sec. 7.3).
  const Affine2 M = pose(0.9, -0.3, 0.3, 0.9, 1.0, 0.5), P0 = pose(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
  const AffinePowers powers(M);
  std::vector<Affine2> poses;
  for (int i = 0; i < 5; ++i) poses.push_back(compose(powers.at(i), P0));
  const std::vector<Affine2> finer = subdivide_four_point(poses);
  ASSERT_EQ(finer.size(), 9u);
  for (std::size_t j = 0; j < finer.size(); ++j) {
    EXPECT_LT(distance(finer[j], compose(powers.at(static_cast<double>(j) / 2.0), P0)), 1e-11) << j;
  }
}

}  // namespace
}  // namespace pita

namespace pita {
namespace {

// The SAM patch (Sec. 7.3, Fig. 11).
TEST(SamPatch, CornersAndRegularRows) {
  const Affine2 A = pose(1.0, 0.0, 0.0, 1.0, 0.0, 5.0), B = pose(0.5, -0.9, 0.9, 0.5, 8.0, 6.0),
                C = pose(1.2, 0.3, 0.0, 0.8, 0.5, 0.0), D = pose(0.3, -1.1, 1.0, 0.6, 9.0, 0.0);
  EXPECT_LT(distance(sam_patch(A, B, C, D, 0.0, 0.0), A), 1e-15);
  EXPECT_LT(distance(sam_patch(A, B, C, D, 1.0, 0.0), B), 1e-12);
  EXPECT_LT(distance(sam_patch(A, B, C, D, 0.0, 1.0), C), 1e-12);
  EXPECT_LT(distance(sam_patch(A, B, C, D, 1.0, 1.0), D), 1e-12);
  // Regular: every row is the pattern G^u (G = B o A^-1) applied to its first pose.
  const Affine2 regular_D = regular_patch_corner(A, B, C);
  EXPECT_LT(distance(regular_D, compose(compose(B, inverse(A)), C)), 1e-12);
  const AffinePowers G(compose(B, inverse(A)));
  for (const double v : {0.0, 0.4, 1.0}) {
    const Affine2 first = sam_patch(A, B, C, regular_D, 0.0, v);
    for (const double u : {0.25, 0.5, 1.0}) {
      EXPECT_LT(distance(sam_patch(A, B, C, regular_D, u, v), compose(G.at(u), first)), 1e-11)
          << "u = " << u << ", v = " << v;
    }
  }
  // Not so for a general fourth corner.
  const Affine2 first = sam_patch(A, B, C, D, 0.0, 0.5);
  EXPECT_GT(distance(sam_patch(A, B, C, D, 0.5, 0.5), compose(G.at(0.5), first)), 1e-3);
}

}  // namespace
}  // namespace pita
