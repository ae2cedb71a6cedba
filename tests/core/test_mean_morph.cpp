// The non-steady variants of the SMA (src/core/mean_morph.cpp, Sec. 2.7,
// Fig. 4): the Pythagorean means of the path and of the magnitude.
#include <cmath>

#include "core/mean_morph.hpp"
#include "core/steady_morph.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

TEST(MeanMorph, GeometricMeansGiveTheSteadyMorph) {
  Sampler s(16);
  for (int i = 0; i < 200; ++i) {
    const Arrow A = s.arrow(Config::wild), B = s.arrow(Config::wild);
    const double t = s.uniform(-0.5, 1.5);
    EXPECT_TRUE(arrows_near(mean_morph(A, B, t, MeanKind::geometric, MeanKind::geometric), steady_morph(A, B, t), 1e-9,
                            10.0, false));
  }
}

TEST(MeanMorph, VariantsInterpolateWithTheirMeans) {
  Sampler s(17);
  for (const MeanKind path : {MeanKind::arithmetic, MeanKind::harmonic}) {
    for (const MeanKind mag : {MeanKind::arithmetic, MeanKind::geometric, MeanKind::harmonic}) {
      for (int i = 0; i < 50; ++i) {
        const Arrow A = s.arrow(Config::tame), B = s.arrow(Config::tame);
        EXPECT_TRUE(arrows_near(mean_morph(A, B, 0.0, path, mag), A, 1e-12, 10.0, false));
        EXPECT_TRUE(arrows_near(mean_morph(A, B, 1.0, path, mag), B, 1e-10, 10.0, false));
        const Arrow mid = mean_morph(A, B, 0.5, path, mag);
        const double expected_m = mag == MeanKind::arithmetic  ? 0.5 * (A.m + B.m)
                                  : mag == MeanKind::geometric ? std::sqrt(A.m * B.m)
                                                               : 2.0 / (1.0 / A.m + 1.0 / B.m);
        EXPECT_NEAR(mid.m, expected_m, 1e-12 * expected_m);
        // The radius about the SMA's fixed point follows the path mean.
        const Point f = *fixed_point(twirl_between(A, B));
        const double ra = std::abs(A.p - f), rb = std::abs(B.p - f);
        const double expected_r = path == MeanKind::arithmetic ? 0.5 * (ra + rb) : 2.0 / (1.0 / ra + 1.0 / rb);
        EXPECT_NEAR(std::abs(mid.p - f), expected_r, 1e-9 * (1 + expected_r));
      }
    }
  }
}

// Found by the independent oracle (tests/oracle): the magnitude must keep its
// relative precision far from the keyframes, whatever the path mean.
TEST(MeanMorph, MagnitudeKeepsRelativePrecision) {
  const Arrow A{{0.0, 0.0}, 1.0, 0.0}, B{{1.0, 0.0}, 20.0, 1.0};
  for (MeanKind path : {MeanKind::arithmetic, MeanKind::geometric, MeanKind::harmonic}) {
    const double m = mean_morph(A, B, -12.0, path, MeanKind::geometric).m;
    EXPECT_NEAR(m / std::pow(20.0, -12.0), 1.0, 1e-13);
    EXPECT_NEAR(mean_morph(A, B, 0.25, path, MeanKind::arithmetic).m, 1.0 + 0.25 * 19.0, 1e-14);
    EXPECT_NEAR(mean_morph(A, B, 0.25, path, MeanKind::harmonic).m, 1.0 / (0.75 + 0.25 / 20.0), 1e-14);
  }
}

// mean(1, lambda, t) - 1 for lambda = 4, t = 1/2: (1 + 4)/2 - 1, sqrt(4) - 1,
// 1/(1/2 + 1/8) - 1.
TEST(MeanOfOneAndMinusOne, IsEachMeanMinusOne) {
  const double log4 = std::log(4.0);
  EXPECT_NEAR(mean_of_one_and_minus_one(MeanKind::arithmetic, log4, 0.5), 1.5, 1e-15);
  EXPECT_NEAR(mean_of_one_and_minus_one(MeanKind::geometric, log4, 0.5), 1.0, 1e-15);
  EXPECT_NEAR(mean_of_one_and_minus_one(MeanKind::harmonic, log4, 0.5), 0.6, 1e-15);
  for (const MeanKind kind : {MeanKind::arithmetic, MeanKind::geometric, MeanKind::harmonic}) {
    EXPECT_EQ(mean_of_one_and_minus_one(kind, log4, 0.0), 0.0);
    EXPECT_NEAR(mean_of_one_and_minus_one(kind, log4, 1.0), 3.0, 1e-15);  // lambda - 1
  }
}

// For lambda = e^eps, every mean of 1 and lambda is 1 + t eps (1 + O(eps)):
// subtracting 1 from the mean itself would keep only about 1e-16 / (t eps) of it.
TEST(MeanOfOneAndMinusOne, KeepsRelativePrecisionNearOne) {
  const double eps = 1e-10, t = 0.3;
  for (const MeanKind kind : {MeanKind::arithmetic, MeanKind::geometric, MeanKind::harmonic}) {
    EXPECT_NEAR(mean_of_one_and_minus_one(kind, eps, t) / (t * eps), 1.0, 1e-9);
  }
}

// Equal magnitudes and windings: the twirl from A to B is a translation, and
// every variant moves p along the segment at constant speed.
TEST(MeanMorph, TranslationMovesAlongTheSegment) {
  const Arrow A{{1.0, 2.0}, 1.5, 0.7}, B{{4.0, -2.0}, 1.5, 0.7};
  for (const MeanKind path : {MeanKind::arithmetic, MeanKind::geometric, MeanKind::harmonic}) {
    for (const double t : {-0.5, 0.25, 0.5, 1.5}) {
      const Arrow D = mean_morph(A, B, t, path, MeanKind::arithmetic);
      EXPECT_NEAR(D.p.real(), 1.0 + 3.0 * t, 1e-14) << t;
      EXPECT_NEAR(D.p.imag(), 2.0 - 4.0 * t, 1e-14) << t;
      EXPECT_NEAR(D.m, 1.5, 1e-15);
      EXPECT_NEAR(D.w, 0.7, 1e-15);
    }
  }
}

}  // namespace
}  // namespace pita::test
