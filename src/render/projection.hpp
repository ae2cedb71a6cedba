// How a 3D pose scene is seen ("camera", scene/figure.hpp): the projection of
// space onto the figure's plane, orthographic or perspective, and the flat
// shading of a face from a light fixed to the camera.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "render/drawing.hpp"
#include "scene/figure.hpp"

namespace pita::render {

class Projection {
 public:
  // Throws std::invalid_argument when a perspective camera has distance <= 0.
  Projection(const scene::Camera& camera, const Eigen::Vector3d& target);
  // The image of x; for perspective, nullopt when x is not in front of the
  // camera (depth <= 1e-9 of the distance).
  std::optional<Point> project(const Eigen::Vector3d& x) const;
  // Distance from the camera's plane along the view direction (larger: farther).
  double depth(const Eigen::Vector3d& x) const;
  // The point at `depth` whose image is `image`: where `pita serve --edit`
  // moves a corner dragged in the view's plane (its depth kept).
  Eigen::Vector3d unproject(Point image, double depth) const;
  // Unit vectors: towards the target, right and up on the image.
  const Eigen::Vector3d& forward() const { return forward_; }
  const Eigen::Vector3d& right() const { return right_; }
  const Eigen::Vector3d& up() const { return up_; }

 private:
  Eigen::Vector3d target_, eye_, forward_, right_, up_;
  double distance_;
  bool perspective_;
};

// The brightness factor of a face with unit `normal` (either side lit), in [0.35, 1].
double face_shade(const Eigen::Vector3d& normal, const Projection& projection);

}  // namespace pita::render
