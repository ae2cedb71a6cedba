#include "scene/body_points.hpp"

namespace pita::scene {

template <class Pose>
std::vector<typename PoseTraits<Pose>::BodyPoint> body_points(const Scene& scene, const Panel& panel) {
  std::vector<typename PoseTraits<Pose>::BodyPoint> points;
  using Keys = PoseKeys<Pose>;
  for (const ShapeOf<Pose>& shape : figure_of<Keys>(panel).shapes) {
    const std::vector<typename PoseTraits<Pose>::BodyPoint>& given = points_of(shape);
    points.insert(points.end(), given.begin(), given.end());
  }
  if (points.empty()) {
    const typename PoseTraits<Pose>::Simplex& reference = figure_of<Keys>(scene).reference;
    points.assign(reference.begin(), reference.end());
  }
  return points;
}

template std::vector<Point> body_points<Affine2>(const Scene&, const Panel&);
template std::vector<Eigen::Vector3d> body_points<Affine3>(const Scene&, const Panel&);

}  // namespace pita::scene
