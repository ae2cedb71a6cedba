// The solids of a 3D pose scene drawn at a pose: each face projected by the
// panel's camera, filled with flat shading or outlined, and painted back to
// front (the painter's algorithm; docs/reference/pose-scenes.md "3D pose scenes").
#pragma once

#include <optional>
#include <vector>

#include "core/affine3.hpp"
#include "render/drawing.hpp"
#include "render/pose_panel.hpp"
#include "scene/figure.hpp"

namespace pita::render {

// Newell's area vector of a polygon of space (any winding, not necessarily
// planar): its unit normal times its area; zero for a degenerate polygon.
Eigen::Vector3d area_vector(const std::vector<Eigen::Vector3d>& points);

// A face to paint, how far its solid is (the mean depth of the solid's
// vertices) and how far the face itself is.
struct Face {
  double solid_depth = 0.0;
  double depth = 0.0;
  int index = -1;
  Shape shape;
  int body = 0;                        // which posed solid (add_solid_faces counts them)
  std::vector<Eigen::Vector3d> world;  // its corners in space (for its shadow)
  double opacity = 1.0;
};

// The faces of `solid` under `pose`: filled and shaded (`fill` given) or as
// closed outlines (a wireframe), each with its depth, appended to `out`.
void add_solid_faces(const PosePanel<Affine3>& panel, const scene::Solid& solid, const Affine3& pose,
                     const std::optional<Color>& fill, const LineStyle& line, double opacity, int index,
                     std::vector<Face>& out);

// Back to front: solid by solid (by the mean depth of their vertices: no face
// of a nearer solid under a farther one unless the solids overlap), and within
// a solid face by face. With "camera": {"shadow": ...}, each solid also casts
// its shadow (PosePanel::cast_shadow).
void paint_faces(PosePanel<Affine3>& panel, std::vector<Face> faces, bool moving);

}  // namespace pita::render
