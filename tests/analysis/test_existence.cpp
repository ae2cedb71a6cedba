// Where a SAM exists (src/analysis/existence.cpp): EAR's classification of
// R(a) diag(1/s, s) against the closed-form boundary of the SAM paper's SAM Eq. 4.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "analysis/existence.hpp"
#include "core/complex_math.hpp"

namespace pita::analysis {
namespace {

TEST(Existence, ClassificationAgreesWithEq4AwayFromTheBoundary) {
  int checked = 0;
  for (int j = 1; j < 100; ++j) {
    const double s = j / 100.0;
    for (int i = -180; i <= 180; ++i) {
      const double a = kPi * i / 180.0;
      const double margin = std::abs(std::abs(a) - existence_boundary(s));
      if (margin < 1e-6) continue;
      EXPECT_EQ(sam_exists(a, s), std::abs(a) < existence_boundary(s)) << "a = " << a << ", s = " << s;
      ++checked;
    }
  }
  EXPECT_GT(checked, 30000);
}

TEST(Existence, TheTrapezoidLiesInsideTheRegion) {
  for (int j = 1; j <= 100; ++j) {
    const double s = j / 100.0;
    EXPECT_LE(std::min(existence_trapezoid(s), kPi), existence_boundary(s) + 1e-12) << s;
  }
  EXPECT_NEAR(existence_boundary(1.0), kPi, 1e-7);       // rotations: every angle but pi
  EXPECT_NEAR(existence_boundary(1e-9), kPi / 2, 1e-8);  // extreme stretches: up to a quarter turn
}

TEST(Existence, GridMarksTheCellsWithoutASam) {
  const ExistenceGrid grid = classify_existence(36, 10);
  ASSERT_EQ(grid.no_sam.size(), 360u);
  // The cell at a ~ 0 (centre column) always has a SAM; the outermost columns
  // (|a| ~ pi) have none for strong stretches (bottom row, s = 0.05).
  EXPECT_FALSE(grid.no_sam[0 * 36 + 18]);
  EXPECT_TRUE(grid.no_sam[0 * 36 + 0]);
  EXPECT_TRUE(grid.no_sam[0 * 36 + 35]);
  for (int j = 0; j < 10; ++j) {
    const double s = (j + 0.5) / 10.0;
    for (int i = 0; i < 36; ++i) {
      const double a = -kPi + (i + 0.5) * 2 * kPi / 36;
      EXPECT_EQ(grid.no_sam[static_cast<std::size_t>(j) * 36 + i], !sam_exists(a, s));
    }
  }
}

}  // namespace
}  // namespace pita::analysis
