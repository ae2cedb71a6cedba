// The geometry of a 3D pose scene ("dimension": 3; README "3D pose
// scenes"): its solids moved by the scene's motion and seen by its camera,
// projected onto the image plane, whose coordinates are the figure's world
// coordinates. Faces are filled back to front (the painter's algorithm,
// within each layer) with flat shading from a fixed light, or drawn as
// wireframes when the layer has no fill.
#pragma once

#include <Eigen/Core>

#include "render/drawing.hpp"
#include "render/panel_drawing.hpp"
#include "scene/scene.hpp"

namespace pita::render {

// The camera's projection: a point of space to the image plane (x right, y
// up) and its depth along the view direction.
class Projection {
 public:
  // Throws std::invalid_argument when a perspective camera has distance <= 0.
  Projection(const scene::Camera& camera, const Eigen::Vector3d& target);
  // The image of x; for perspective, nullopt when x is not in front of the
  // camera (depth <= 1e-9 of the distance).
  std::optional<Point> project(const Eigen::Vector3d& x) const;
  // Distance from the camera's plane along the view direction (larger: farther).
  double depth(const Eigen::Vector3d& x) const;
  // Unit vectors: towards the target, right and up on the image.
  const Eigen::Vector3d& forward() const { return forward_; }
  const Eigen::Vector3d& right() const { return right_; }
  const Eigen::Vector3d& up() const { return up_; }

 private:
  Eigen::Vector3d target_, eye_, forward_, right_, up_;
  double distance_;
  bool perspective_;
};

// The brightness of a face with unit normal n under the fixed light (from
// the camera's side, above and to the left): 0.35 ambient + 0.65 |n . l|.
double face_shade(const Eigen::Vector3d& normal, const Projection& projection);

// The shapes of every layer of the 3D scene, in drawing order. Throws
// RenderError. With a selection (an animation frame) the "shapes" layers draw
// the selection's time and trail only.
Drawing space_panel_drawing(const scene::Scene& scene, const scene::Panel& panel,
                            const FrameSelection* selection = nullptr);
// The same for the stage's panel `index`, with the motion the stage built.
Drawing space_panel_drawing(const motion::Stage& stage, std::size_t index, const FrameSelection* selection = nullptr);

}  // namespace pita::render
