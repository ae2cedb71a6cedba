// "paths": the path of every point of the body (every point of the shapes;
// every vertex of the solids) over the layer's frames.
#include <vector>

#include <fmt/format.h>

#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"

namespace pita::render {

template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::PathsLayer& layer) {
  std::vector<Pose> poses;
  for (const double t : panel.times(layer.samples, layer.range)) poses.push_back(panel.pose_at(t));
  for (const BodyPoint<Pose>& x : panel.body_points()) {
    std::vector<Point> path;
    path.reserve(poses.size());
    for (const Pose& pose : poses) path.push_back(panel.image(pita::apply(pose, x)));
    panel.push(-1, Polyline{std::move(path), false, layer.line});
  }
}

template void draw_pose_layer(PosePanel<Affine2>&, const scene::PathsLayer&);
template void draw_pose_layer(PosePanel<Affine3>&, const scene::PathsLayer&);

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::PathsLayer& l) {
  add(layer_ + "/samples", fmt::format("{} points of each vertex's path", l.samples),
      shape_points() * (kShapeUnits + l.samples));
}

}  // namespace detail

}  // namespace pita::render
