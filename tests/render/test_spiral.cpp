// The coil that shows an arrow's winding (src/render/spiral.cpp): it turns
// through w from angle 0, its radius growing linearly from 0.1 m to 0.3 m.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "render/spiral.hpp"

namespace pita::render {
namespace {

TEST(WindingSpiral, StartsAlongXAndEndsInTheArrowsDirection) {
  const Point c{2.0, -1.0};
  const double m = 5.0, w = 2.5 * kPi;  // a turn and a quarter, ending straight up
  const std::vector<Point> spiral = winding_spiral(c, m, w);
  ASSERT_GE(spiral.size(), 2u);
  EXPECT_NEAR(std::abs(spiral.front() - (c + Point{0.5, 0.0})), 0.0, 1e-15);  // 0.1 m along x
  EXPECT_NEAR(std::abs(spiral.back() - (c + Point{0.0, 1.5})), 0.0, 1e-14);   // 0.3 m along y
}

// Angle and radius of every point grow together: radius = m (0.1 + 0.2 angle / w).
TEST(WindingSpiral, RadiusGrowsLinearlyWithTheAngle) {
  const double m = 2.0, w = -3.0 * kPi;  // clockwise, a turn and a half
  const std::vector<Point> spiral = winding_spiral({0.0, 0.0}, m, w);
  double previous_angle = 0.0;
  for (const Point p : spiral) {
    const double radius = std::abs(p);
    const double angle = w * (radius / m - 0.1) / 0.2;  // the angle this radius belongs to
    EXPECT_NEAR(std::abs(p - std::polar(radius, angle)), 0.0, 1e-12);
    EXPECT_LE(angle, previous_angle + 1e-12);  // clockwise: decreasing
    previous_angle = angle;
  }
  EXPECT_NEAR(previous_angle, w, 1e-12);
}

TEST(WindingSpiral, PointCountFollowsTheTurnsWithinItsLimits) {
  EXPECT_TRUE(winding_spiral({0.0, 0.0}, 1.0, 0.0).empty());
  EXPECT_TRUE(winding_spiral({0.0, 0.0}, 1.0, 1e-10).empty());
  EXPECT_TRUE(winding_spiral({0.0, 0.0}, 1.0, std::nan("")).empty());
  // Two turns: 2 * 72 + 1 segments, so 146 points; a tiny winding still 9.
  EXPECT_EQ(winding_spiral({0.0, 0.0}, 1.0, 4.0 * kPi).size(), 146u);
  EXPECT_EQ(winding_spiral({0.0, 0.0}, 1.0, 1e-3).size(), 9u);
  // 1000 turns are drawn with the most points allowed.
  EXPECT_EQ(winding_spiral({0.0, 0.0}, 1.0, 2000.0 * kPi).size(), static_cast<std::size_t>(kMaxSpiralPoints) + 1u);
}

}  // namespace
}  // namespace pita::render
