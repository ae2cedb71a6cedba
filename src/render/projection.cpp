#include "render/projection.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "render/camera_choice.hpp"

namespace pita::render {

Projection::Projection(const scene::Camera& camera, const Eigen::Vector3d& target)
    : target_(target), distance_(camera.distance), perspective_(camera.perspective) {
  using Eigen::Vector3d;
  if (perspective_ && !(distance_ > 0.0)) {
    throw std::invalid_argument(fmt::format("a perspective camera needs a distance > 0 (got {:g})", distance_));
  }
  const Vector3d eye_direction = towards_eye(camera.azimuth, camera.elevation);
  eye_ = target_ + distance_ * eye_direction;
  forward_ = -eye_direction;
  const Vector3d world_up = std::abs(forward_.z()) > 0.999 ? Vector3d::UnitY() : Vector3d::UnitZ();
  right_ = forward_.cross(world_up).normalized();
  up_ = right_.cross(forward_);
}

std::optional<Point> Projection::project(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d d = x - target_;
  double scale = 1.0;
  if (perspective_) {
    const double depth = (x - eye_).dot(forward_);
    if (!(depth > 1e-9 * distance_)) return std::nullopt;
    scale = distance_ / depth;
  }
  return Point{scale * d.dot(right_), scale * d.dot(up_)};
}

double Projection::depth(const Eigen::Vector3d& x) const { return (x - eye_).dot(forward_); }

Eigen::Vector3d Projection::unproject(Point image, double depth) const {
  // project() scales by distance / depth in perspective; orthographic, by 1.
  const double scale = perspective_ ? depth / distance_ : 1.0;
  return eye_ + depth * forward_ + scale * (image.real() * right_ + image.imag() * up_);
}

double face_shade(const Eigen::Vector3d& normal, const Projection& projection) {
  const Eigen::Vector3d light = (-projection.forward() + 0.8 * projection.up() - 0.5 * projection.right()).normalized();
  return 0.35 + 0.65 * std::abs(normal.dot(light));
}

}  // namespace pita::render
