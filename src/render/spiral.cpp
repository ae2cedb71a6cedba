#include "render/spiral.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pita::render {

std::vector<Point> winding_spiral(Point center, double m, double w) {
  std::vector<Point> points;
  if (!(std::abs(w) > 1e-9)) return points;
  const double turns = std::abs(w) / (2.0 * std::numbers::pi);
  const int n = std::clamp(static_cast<int>(std::ceil(turns * kSpiralPointsPerTurn)) + 1, 8, kMaxSpiralPoints);
  points.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    const double radius = m * (kSpiralInner + (kSpiralOuter - kSpiralInner) * s);
    points.push_back(center + std::polar(radius, s * w));
  }
  return points;
}

}  // namespace pita::render
