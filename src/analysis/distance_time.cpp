#include "analysis/distance_time.hpp"

#include "core/arc_length.hpp"

namespace pita::analysis {

std::vector<Point> distance_time(const motion::SceneMotion& motion, scene::TrackedPoint point,
                                 std::span<const double> times) {
  const ArcLengthTable table(motion.point_path(point), motion.first(), motion.last());
  const double duration = motion.last() - motion.first();
  std::vector<Point> curve;
  curve.reserve(times.size());
  for (const double t : times) {
    curve.push_back({(t - motion.first()) / duration, table.length_at(motion.motion_time(t)) / table.length()});
  }
  return curve;
}

}  // namespace pita::analysis
