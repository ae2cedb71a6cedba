#include "scene/body_points.hpp"

namespace pita::scene {

template <class Pose>
std::vector<typename PoseTraits<Pose>::BodyPoint> body_points(const Scene& scene, const Panel& panel) {
  std::vector<typename PoseTraits<Pose>::BodyPoint> points;
  if constexpr (!in_space_v<Pose>) {
    for (const ShapeOutline& shape : panel.shapes) {
      points.insert(points.end(), shape.points.begin(), shape.points.end());
    }
    if (points.empty()) points.assign(scene.reference_triangle.begin(), scene.reference_triangle.end());
  } else {
    for (const Solid& solid : scene.solids) points.insert(points.end(), solid.vertices.begin(), solid.vertices.end());
    if (points.empty()) points.assign(scene.reference_tetrahedron.begin(), scene.reference_tetrahedron.end());
  }
  return points;
}

template std::vector<Point> body_points<Affine2>(const Scene&, const Panel&);
template std::vector<Eigen::Vector3d> body_points<Affine3>(const Scene&, const Panel&);

}  // namespace pita::scene
