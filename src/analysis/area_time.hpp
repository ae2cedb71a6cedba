// The area of a pose scene's moving shapes over time (SAM paper Sec. 6.3,
// Fig. 9; docs/paper-notes.md N48): A(t) maps every shape's area by
// |det L(t)|, so the area relative to the shapes' reference area is
// |det L(t)|. Under a SAM, det L(t) = det(B) e^{u trace(log L)} (B the first
// pose, u the span's time) is monotonic; under rARAP it need not be.
// Monotonicity is judged by analysis::area_stats, as `pita measure` does.
#pragma once

#include <span>
#include <vector>

#include "analysis/measure.hpp"
#include "motion/scene_motion.hpp"

namespace pita::analysis {

struct AreaCurve {
  std::vector<double> times;  // scene times
  std::vector<double> areas;  // |det L(t)|: area over reference area
  AreaStats stats;            // of det L(t) at `times`
  double smallest = 0.0, largest = 0.0;
  double t_of_largest = 0.0, t_of_smallest = 0.0;
};

// The area at each scene time. Throws NoMotion where the motion is undefined.
AreaCurve area_over_time(const motion::SceneMotion& motion, std::span<const double> times);

}  // namespace pita::analysis
