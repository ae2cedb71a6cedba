#include "core/steadiness.hpp"

#include <Eigen/LU>

#include "core/limits.hpp"

namespace pita {

namespace {

template <class Motion, class Vector>
double relative_acceleration_mean(const Motion& motion, std::span<const Vector> points, int time_samples) {
  const auto& poses = motion.poses();
  const double first = poses.front().t, duration = poses.back().t - first;
  // w(u) for every point at normalised time u (velocity per unit of u).
  const auto relative_velocity = [&](double u, const Vector& p) {
    const double t = first + u * duration;
    const auto pose = motion.at(t);
    const auto rate = motion.velocity(t);
    return Vector(pose.L.inverse() * (rate.L * p + rate.b) * duration);
  };
  const double h = limits::kSteadinessStep / time_samples;
  double sum = 0.0;
  for (int i = 0; i < time_samples; ++i) {
    const double u = (i + 0.5) / time_samples;
    for (const Vector& p : points) {
      sum += ((relative_velocity(u + h, p) - relative_velocity(u - h, p)) / (2.0 * h)).norm();
    }
  }
  return sum / (static_cast<double>(time_samples) * static_cast<double>(points.size()));
}

}  // namespace

double average_relative_acceleration(const PoseMotion& motion, std::span<const Eigen::Vector2d> points,
                                     int time_samples) {
  return relative_acceleration_mean(motion, points, time_samples);
}

double average_relative_acceleration(const PoseMotion3& motion, std::span<const Eigen::Vector3d> points,
                                     int time_samples) {
  return relative_acceleration_mean(motion, points, time_samples);
}

}  // namespace pita
