#include "core/steadiness.hpp"

#include <Eigen/LU>

#include "core/finite_difference.hpp"
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
      sum += central_derivative([&](double v) { return relative_velocity(v, p); }, u, h).norm();
    }
  }
  return sum / (static_cast<double>(time_samples) * static_cast<double>(points.size()));
}

}  // namespace

double average_relative_acceleration(const PoseMotion& motion, std::span<const Eigen::Vector2d> points,
                                     int time_samples) {
  return relative_acceleration_mean(motion, points, time_samples);
}

double average_relative_acceleration(const SamFamilyMotion<Affine3>& motion, std::span<const Eigen::Vector3d> points,
                                     int time_samples) {
  return relative_acceleration_mean(motion, points, time_samples);
}

std::vector<Eigen::Vector2d> ara_grid(std::span<const Eigen::Vector2d> vertices, int per_side) {
  if (vertices.empty() || per_side < 2) return {vertices.begin(), vertices.end()};
  Eigen::Vector2d low = vertices.front(), high = low;
  for (const Eigen::Vector2d& v : vertices) {
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  std::vector<Eigen::Vector2d> grid;
  grid.reserve(static_cast<std::size_t>(per_side) * static_cast<std::size_t>(per_side));
  for (int i = 0; i < per_side; ++i) {
    for (int j = 0; j < per_side; ++j) {
      grid.emplace_back(low.x() + (high.x() - low.x()) * i / (per_side - 1),
                        low.y() + (high.y() - low.y()) * j / (per_side - 1));
    }
  }
  return grid;
}

}  // namespace pita
