// ASAP, Fig. 2 (c) of the SAM paper (core/spiral_residue_morph.hpp): a log
// spiral for position, orientation and uniform scale, and a linear residue.
#include <cmath>
#include <complex>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/affine_power.hpp"
#include "core/spiral_residue_morph.hpp"
#include "core/steady_affine_morph.hpp"
#include "fig2_morph_support.hpp"

namespace pita {
namespace {

using test::distance;

const Eigen::Vector2d kSpiralCentre(1.0 / 3.0, 1.0 / 3.0);

Point point_of(const Eigen::Vector2d& x) { return {x.x(), x.y()}; }

TEST(SpiralResidueMorph, InterpolatesBothPoses) {
  for (const auto& [from, to] :
       {std::pair{test::kFig2From, test::kFig2To}, std::pair{test::kOtherFrom, test::kOtherTo}}) {
    const SpiralResidueMorph morph(from, to, kSpiralCentre);
    EXPECT_LT(distance(morph.at(0.0), from), 1e-12);
    EXPECT_LT(distance(morph.at(1.0), to), 1e-12);
  }
}

// The similarity part is steady: the barycentre runs on the log spiral about
// the fixed point of z -> lambda (z - g0) + g1, lambda = sqrt(det L) e^{i theta},
// theta the polar angle of L (closed forms, independent of the morph), and the
// pose's uniform scale is (det L)^{u/2} times the residue's.
TEST(SpiralResidueMorph, SimilarityPartIsALogSpiral) {
  const Affine2 A = compose(test::kFig2To, inverse(test::kFig2From));
  const double theta = std::atan2(A.L(1, 0) - A.L(0, 1), A.L(0, 0) + A.L(1, 1));
  const Complex log_lambda{0.5 * std::log(A.L.determinant()), theta};
  const Point g0 = point_of(apply(test::kFig2From, kSpiralCentre)), g1 = point_of(apply(test::kFig2To, kSpiralCentre));
  const Point f = test::spiral_centre(std::exp(log_lambda), g0, g1);
  const SpiralResidueMorph morph(test::kFig2From, test::kFig2To, kSpiralCentre);
  for (const double u : {0.0, 0.2, 0.5, 0.75, 1.0}) {
    SCOPED_TRACE(u);
    const Point expected = test::on_spiral(f, log_lambda, u, g0);
    EXPECT_LT(std::abs(point_of(apply(morph.at(u), kSpiralCentre)) - expected), 1e-12);
    // det of M(u)'s linear part = s^{2u} det((1 - u) I + u N).
    const Eigen::Matrix2d K = (1.0 - u) * Eigen::Matrix2d::Identity() + u * morph.residue();
    const Eigen::Matrix2d M = morph.at(u).L * test::kFig2From.L.inverse();
    EXPECT_NEAR(M.determinant(), std::exp(2.0 * u * log_lambda.real()) * K.determinant(), 1e-12);
  }
  // The residue is the stretch without its uniform scale: symmetric, det 1.
  EXPECT_NEAR(morph.residue().determinant(), 1.0, 1e-12);
  EXPECT_NEAR(morph.residue()(0, 1), morph.residue()(1, 0), 1e-15);
}

// Between similar poses the residue is the identity and the morph is the SAM.
TEST(SpiralResidueMorph, IsTheSamBetweenSimilarPoses) {
  const Affine2 from = test::kOtherFrom;
  const Affine2 to = compose(test::similarity(2.5, -2.0, 3.0, 1.0), from);
  const SpiralResidueMorph morph(from, to, kSpiralCentre);
  for (const double u : {0.2, 0.5, 0.9}) {
    EXPECT_LT(distance(morph.at(u), steady_affine_morph(from, to, u)), 1e-11) << "u = " << u;
  }
}

TEST(SpiralResidueMorph, VelocityIsTheDerivative) {
  const SpiralResidueMorph morph(test::kFig2From, test::kFig2To, kSpiralCentre);
  for (const double u : {0.0, 0.3, 0.9}) {
    SCOPED_TRACE(u);
    EXPECT_LT(distance(morph.velocity(u), test::central_difference(morph, u)), 1e-7);
  }
}

TEST(SpiralResidueMorph, SimilarityInvariant) {
  const Affine2 S = test::similarity(0.6, -2.2, 5.0, 1.0);
  const SpiralResidueMorph morph(test::kOtherFrom, test::kOtherTo, kSpiralCentre);
  const SpiralResidueMorph moved(compose(S, test::kOtherFrom), compose(S, test::kOtherTo), kSpiralCentre);
  for (const double u : {0.25, 0.5, 0.75}) {
    EXPECT_LT(distance(moved.at(u), compose(S, morph.at(u))), 1e-11) << "u = " << u;
  }
}

TEST(SpiralResidueMorph, RefusesOppositeOrientations) {
  EXPECT_THROW(SpiralResidueMorph(test::kFig2From, test::pose(0.0, 1.0, 1.0, 0.0, 0.0, 0.0), kSpiralCentre),
               std::invalid_argument);
}

}  // namespace
}  // namespace pita
