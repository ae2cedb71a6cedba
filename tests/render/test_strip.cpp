// The quad strip of a pattern (src/render/strip.cpp): quads between
// consecutive frames and their bilinear (along, across) parameterisation.
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "render/strip.hpp"

namespace pita::render {
namespace {

// Three frames, p on the x axis, q = p + (0, 1), (0, 2), (0, 1) (m and w).
const std::vector<Arrow> kFrames = {Arrow{{0.0, 0.0}, 1.0, 1.5707963267948966},
                                    Arrow{{2.0, 0.0}, 2.0, 1.5707963267948966},
                                    Arrow{{4.0, 0.0}, 1.0, 1.5707963267948966}};

double strip_gap(Point a, Point b) { return std::abs(a - b); }

TEST(QuadStrip, QuadsJoinConsecutiveFramesPQQP) {
  const QuadStrip strip(kFrames);
  EXPECT_EQ(strip.quad_count(), 2);
  const std::array<Point, 4> second = strip.quad(1);
  EXPECT_LT(strip_gap(second[0], {2.0, 0.0}), 1e-15);
  EXPECT_LT(strip_gap(second[1], {2.0, 2.0}), 1e-15);
  EXPECT_LT(strip_gap(second[2], {4.0, 1.0}), 1e-15);
  EXPECT_LT(strip_gap(second[3], {4.0, 0.0}), 1e-15);
}

TEST(QuadStrip, AtIsBilinearInsideEachQuad) {
  const QuadStrip strip(kFrames);
  EXPECT_LT(strip_gap(strip.at(0.0, 0.0), {0.0, 0.0}), 1e-15);
  EXPECT_LT(strip_gap(strip.at(0.0, 1.0), {0.0, 1.0}), 1e-15);
  EXPECT_LT(strip_gap(strip.at(2.0, 1.0), {4.0, 1.0}), 1e-15);  // the last frame's q
  // Middle of the first quad: the mean of its corners (0, 0), (0, 1), (2, 2), (2, 0).
  EXPECT_LT(strip_gap(strip.at(0.5, 0.5), {1.0, 0.75}), 1e-15);
  // u = 1.25, v = 0.5: a quarter of the way from (2, 1) to (4, 0.5).
  EXPECT_LT(strip_gap(strip.at(1.25, 0.5), {2.5, 0.875}), 1e-15);
}

TEST(QuadStrip, AlongIsClampedToTheStrip) {
  const QuadStrip strip(kFrames);
  EXPECT_LT(strip_gap(strip.at(-3.0, 0.5), {0.0, 0.5}), 1e-15);
  EXPECT_LT(strip_gap(strip.at(7.0, 0.0), {4.0, 0.0}), 1e-15);
}

TEST(QuadStrip, NeedsTwoFrames) {
  const std::vector<Arrow> one(kFrames.begin(), kFrames.begin() + 1);
  const std::vector<Arrow> two(kFrames.begin(), kFrames.begin() + 2);
  EXPECT_THROW(QuadStrip{one}, std::invalid_argument);
  EXPECT_EQ(QuadStrip{two}.quad_count(), 1);
}

}  // namespace
}  // namespace pita::render
