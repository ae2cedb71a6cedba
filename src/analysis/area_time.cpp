#include "analysis/area_time.hpp"

#include <cmath>

namespace pita::analysis {

AreaCurve area_over_time(const motion::SceneMotion& motion, std::span<const double> times) {
  AreaCurve curve;
  std::vector<double> dets;
  for (const double t : times) {
    const double det = motion.pose_at<Affine2>(t).L.determinant();
    curve.times.push_back(t);
    dets.push_back(det);
    const double area = std::abs(det);
    if (curve.areas.empty() || area > curve.largest) {
      curve.largest = area;
      curve.t_of_largest = t;
    }
    if (curve.areas.empty() || area < curve.smallest) {
      curve.smallest = area;
      curve.t_of_smallest = t;
    }
    curve.areas.push_back(area);
  }
  curve.stats = area_stats(curve.times, dets);
  return curve;
}

}  // namespace pita::analysis
