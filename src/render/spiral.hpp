// The coil that shows an arrow's winding w (Fig. 1-3): a spiral around a
// centre that turns through the angle w, starting along the x axis (angle 0)
// and ending in the direction of the arrow, its radius growing linearly from
// kSpiralInner m to kSpiralOuter m so that each extra turn is visible.
#pragma once

#include <vector>

#include "core/arrow.hpp"

namespace pita::render {

inline constexpr double kSpiralInner = 0.10;  // radius at angle 0, in units of m
inline constexpr double kSpiralOuter = 0.30;  // radius at angle w
inline constexpr int kSpiralPointsPerTurn = 72;
inline constexpr int kMaxSpiralPoints = 20'000;  // windings beyond ~277 turns are drawn coarser

// The spiral's points; empty when |w| is below 1e-9 (nothing to show).
std::vector<Point> winding_spiral(Point center, double m, double w);

}  // namespace pita::render
