// rARAP, Fig. 2 (b) of the SAM paper (core/rarap_morph.hpp): it interpolates
// the poses, turns at a constant rate (the polar angle of L(u) is linear in
// u), moves the barycentre at constant speed on a line, is similarity-
// invariant, and is not steady.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/affine_power.hpp"
#include "core/rarap_morph.hpp"
#include "core/steadiness.hpp"
#include "core/steady_affine_morph.hpp"
#include "fig2_morph_support.hpp"

namespace pita {
namespace {

using test::distance;

const Eigen::Vector2d kCentre(1.0 / 3.0, 1.0 / 3.0);  // of the unit triangle

double polar_angle(const Eigen::Matrix2d& L) { return std::atan2(L(1, 0) - L(0, 1), L(0, 0) + L(1, 1)); }

TEST(RarapMorph, InterpolatesBothPoses) {
  for (const auto& [from, to] :
       {std::pair{test::kFig2From, test::kFig2To}, std::pair{test::kOtherFrom, test::kOtherTo}}) {
    const RarapMorph morph(from, to, kCentre);
    EXPECT_LT(distance(morph.at(0.0), from), 1e-12);
    EXPECT_LT(distance(morph.at(1.0), to), 1e-12);
  }
}

// The rotation angle is linear in u: L(u) = R(u theta) K(u) with K(u) symmetric
// positive definite, so the polar angle of L(u) is u theta; theta is the polar
// angle of C o B^-1 (closed form atan2, independent of the SVD).
TEST(RarapMorph, AngleLinearInTime) {
  const RarapMorph morph(test::kFig2From, test::kFig2To, kCentre);
  const double theta = polar_angle(compose(test::kFig2To, inverse(test::kFig2From)).L);
  EXPECT_GT(std::abs(theta), 0.5);
  for (const double u : {0.1, 0.25, 0.5, 0.8, 1.0}) {
    SCOPED_TRACE(u);
    EXPECT_NEAR(polar_angle(morph.linear(u)), u * theta, 1e-12);
    // and the pose's linear part is L(u) B_L.
    EXPECT_LT((morph.at(u).L - morph.linear(u) * test::kFig2From.L).norm(), 1e-12);
  }
}

// The barycentre of the shape moves at constant speed on the segment between
// its two positions: pose(u)(c) = (1 - u) B(c) + u C(c).
TEST(RarapMorph, BarycentreAtConstantSpeedOnALine) {
  const RarapMorph morph(test::kOtherFrom, test::kOtherTo, kCentre);
  const Eigen::Vector2d g0 = apply(test::kOtherFrom, kCentre), g1 = apply(test::kOtherTo, kCentre);
  for (const double u : {0.0, 0.2, 0.5, 0.7, 1.0}) {
    SCOPED_TRACE(u);
    EXPECT_LT((apply(morph.at(u), kCentre) - ((1.0 - u) * g0 + u * g1)).norm(), 1e-12);
    EXPECT_LT((apply(morph.velocity(u), kCentre) - (g1 - g0)).norm(), 1e-12);
  }
}

TEST(RarapMorph, VelocityIsTheDerivative) {
  const RarapMorph morph(test::kFig2From, test::kFig2To, kCentre);
  for (const double u : {0.0, 0.3, 0.9}) {
    SCOPED_TRACE(u);
    EXPECT_LT(distance(morph.velocity(u), test::central_difference(morph, u)), 1e-7);
  }
}

TEST(RarapMorph, SimilarityInvariant) {
  const Affine2 S = test::similarity(1.7, 0.9, -3.0, 2.0);
  const RarapMorph morph(test::kFig2From, test::kFig2To, kCentre);
  const RarapMorph moved(compose(S, test::kFig2From), compose(S, test::kFig2To), kCentre);
  for (const double u : {0.25, 0.5, 0.75}) {
    EXPECT_LT(distance(moved.at(u), compose(S, morph.at(u))), 1e-11) << "u = " << u;
  }
}

// Not steady: even between similar poses (a turn with a dilation) it scales
// linearly where the SAM scales geometrically.
TEST(RarapMorph, NotTheSamBetweenSimilarPoses) {
  const Affine2 from = test::similarity(1.0, 0.0, 0.0, 0.0);
  const Affine2 to = test::similarity(3.0, 1.2, 4.0, 1.0);
  const RarapMorph morph(from, to, kCentre);
  EXPECT_NEAR(morph.at(0.5).L.determinant(), 4.0, 1e-12);  // ((1 + 3)/2)^2; the SAM: 3
  EXPECT_GT(distance(morph.at(0.5), steady_affine_morph(from, to, 0.5)), 0.1);
}

TEST(RarapMorph, RefusesOppositeOrientations) {
  EXPECT_THROW(RarapMorph(test::kFig2From, test::pose(1.0, 0.0, 0.0, -1.0, 0.0, 0.0), kCentre), std::invalid_argument);
}

}  // namespace
}  // namespace pita
