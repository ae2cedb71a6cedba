#include "core/steadiness.hpp"

#include <Eigen/LU>

namespace pita {

double average_relative_acceleration(const PoseMotion& motion,
                                     std::span<const Eigen::Vector2d> points, int time_samples) {
  const std::vector<TimedPose>& poses = motion.poses();
  const double first = poses.front().t, duration = poses.back().t - first;
  // w(u) for every point at normalised time u (velocity per unit of u).
  const auto relative_velocity = [&](double u, const Eigen::Vector2d& p) {
    const double t = first + u * duration;
    const Affine2 pose = motion.at(t);
    const Affine2 rate = motion.velocity(t);
    return Eigen::Vector2d(pose.L.inverse() * (rate.L * p + rate.b) * duration);
  };
  const double h = 1e-4 / time_samples;
  double sum = 0.0;
  for (int i = 0; i < time_samples; ++i) {
    const double u = (i + 0.5) / time_samples;
    for (const Eigen::Vector2d& p : points) {
      sum += ((relative_velocity(u + h, p) - relative_velocity(u - h, p)) / (2.0 * h)).norm();
    }
  }
  return sum / (static_cast<double>(time_samples) * static_cast<double>(points.size()));
}

}  // namespace pita
