// TSB, Fig. 2 (d) of the SAM paper (core/triangle_spiral_blend.hpp): each
// side's log spiral, their blend with weight 1/2 per vertex, the pose through
// the blended vertices.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "core/affine_power.hpp"
#include "core/steady_affine_morph.hpp"
#include "core/triangle_spiral_blend.hpp"
#include "fig2_morph_support.hpp"

namespace pita {
namespace {

using test::distance;
using test::kUnitTriangle;

TEST(TriangleSpiralBlend, InterpolatesBothPoses) {
  for (const auto& [from, to] :
       {std::pair{test::kFig2From, test::kFig2To}, std::pair{test::kOtherFrom, test::kOtherTo}}) {
    const TriangleSpiralBlend morph(from, to, kUnitTriangle);
    EXPECT_LT(distance(morph.at(0.0), from), 1e-12);
    EXPECT_LT(distance(morph.at(1.0), to), 1e-12);
  }
}

// Side j's spiral maps side j of the first triangle onto side j of the
// second, both ends on log spirals about its fixed point (closed form
// f + lambda^u (x - f), lambda the ratio of the side vectors, principal angle).
TEST(TriangleSpiralBlend, EachSideSpiral) {
  const TriangleSpiralBlend morph(test::kOtherFrom, test::kOtherTo, kUnitTriangle);
  for (int j = 0; j < 3; ++j) {
    SCOPED_TRACE(j);
    const Point a = apply(test::kOtherFrom, kUnitTriangle[j]), b = apply(test::kOtherFrom, kUnitTriangle[(j + 1) % 3]);
    const Point a1 = apply(test::kOtherTo, kUnitTriangle[j]), b1 = apply(test::kOtherTo, kUnitTriangle[(j + 1) % 3]);
    const Complex lambda = (b1 - a1) / (b - a);
    const Complex log_lambda = std::log(lambda);  // principal: Arg in (-pi, pi]
    const Point f = test::spiral_centre(lambda, a, a1);
    const Twirl& T = morph.side_spiral(j);
    EXPECT_LT(std::abs(T.log() - log_lambda), 1e-12);
    EXPECT_LT(std::abs(pita::apply(T, a) - a1), 1e-12);
    EXPECT_LT(std::abs(pita::apply(T, b) - b1), 1e-12);
    for (const double u : {0.3, 0.6}) {
      EXPECT_LT(std::abs(apply_power(T, u, a) - test::on_spiral(f, log_lambda, u, a)), 1e-12);
      EXPECT_LT(std::abs(apply_power(T, u, b) - test::on_spiral(f, log_lambda, u, b)), 1e-12);
    }
  }
}

// Each vertex is the average of its two sides' spirals (weight 1/2 each, none
// for the opposite side), and the pose carries the reference triangle onto
// the blended vertices.
TEST(TriangleSpiralBlend, BlendWeights) {
  EXPECT_EQ(TriangleSpiralBlend::kSideWeight, 0.5);
  const TriangleSpiralBlend morph(test::kFig2From, test::kFig2To, kUnitTriangle);
  std::array<Point, 3> v0{}, v1{};
  for (int j = 0; j < 3; ++j) {
    v0[j] = apply(test::kFig2From, kUnitTriangle[j]);
    v1[j] = apply(test::kFig2To, kUnitTriangle[j]);
  }
  // The spiral of side (i, k) applied to vertex x, in closed form.
  const auto side = [&](int i, int k, double u, Point x) {
    const Complex lambda = (v1[k] - v1[i]) / (v0[k] - v0[i]);
    return test::on_spiral(test::spiral_centre(lambda, v0[i], v1[i]), std::log(lambda), u, x);
  };
  for (const double u : {0.25, 0.5, 0.8}) {
    const Affine2 pose = morph.at(u);
    for (int j = 0; j < 3; ++j) {
      SCOPED_TRACE(::testing::Message() << "u = " << u << ", vertex " << j);
      const Point expected = 0.5 * side(j, (j + 1) % 3, u, v0[j]) + 0.5 * side((j + 2) % 3, j, u, v0[j]);
      EXPECT_LT(std::abs(morph.vertex(j, u) - expected), 1e-12);
      EXPECT_LT(std::abs(pita::apply(pose, kUnitTriangle[j]) - expected), 1e-12);
    }
  }
}

// Between similar triangles the three spirals coincide: TSB is the SAM.
TEST(TriangleSpiralBlend, IsTheSamBetweenSimilarTriangles) {
  const Affine2 from = test::kFig2From;
  const Affine2 to = compose(test::similarity(0.4, 2.7, -1.0, 3.0), from);
  const TriangleSpiralBlend morph(from, to, kUnitTriangle);
  for (const double u : {0.2, 0.5, 0.9}) {
    EXPECT_LT(distance(morph.at(u), steady_affine_morph(from, to, u)), 1e-11) << "u = " << u;
  }
}

TEST(TriangleSpiralBlend, VelocityIsTheDerivative) {
  const TriangleSpiralBlend morph(test::kOtherFrom, test::kOtherTo, kUnitTriangle);
  for (const double u : {0.0, 0.3, 0.9}) {
    SCOPED_TRACE(u);
    EXPECT_LT(distance(morph.velocity(u), test::central_difference(morph, u)), 1e-7);
  }
}

TEST(TriangleSpiralBlend, SimilarityInvariant) {
  const Affine2 S = test::similarity(2.0, 0.7, 1.0, -4.0);
  const TriangleSpiralBlend morph(test::kFig2From, test::kFig2To, kUnitTriangle);
  const TriangleSpiralBlend moved(compose(S, test::kFig2From), compose(S, test::kFig2To), kUnitTriangle);
  for (const double u : {0.25, 0.5, 0.75}) {
    EXPECT_LT(distance(moved.at(u), compose(S, morph.at(u))), 1e-11) << "u = " << u;
  }
}

// It depends on the reference triangle (the sides it blends): not affine-invariant.
TEST(TriangleSpiralBlend, DependsOnTheReferenceTriangle) {
  const std::array<Point, 3> other{Point{0.0, 0.0}, Point{2.0, 0.5}, Point{0.3, 1.0}};
  const TriangleSpiralBlend unit(test::kFig2From, test::kFig2To, kUnitTriangle);
  const TriangleSpiralBlend skew(test::kFig2From, test::kFig2To, other);
  EXPECT_GT(distance(unit.at(0.5), skew.at(0.5)), 1e-3);
}

}  // namespace
}  // namespace pita
