// "velocities": at each of the layer's frames, the velocity of every point of
// the body as an arrow `scale` x dx/du, u the time normalised to the motion
// (exact for SAM: the field x -> log(A) x of SAM Sec. 2.3, SAM Eq. 6).
#include <vector>

#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"

namespace pita::render {

template <class Pose>
void draw_pose_layer(PosePanel<Pose>& panel, const scene::VelocitiesLayer& layer) {
  const std::vector<double> ts = panel.times(layer.samples, layer.range);
  const std::vector<BodyPoint<Pose>> points = panel.body_points();
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Pose pose = panel.pose_at(ts[i]);
    const Pose velocity = panel.velocity_at(ts[i]);
    for (const BodyPoint<Pose>& x : points) {
      const BodyPoint<Pose> from = pita::apply(pose, x);
      const BodyPoint<Pose> rate = pita::apply(velocity, x);  // (dL/du) x + db/du
      const BodyPoint<Pose> to = from + layer.scale * rate;
      panel.push(static_cast<int>(i), ArrowShape{panel.image(from), panel.image(to), layer.line});
    }
  }
}

template void draw_pose_layer(PosePanel<Affine2>&, const scene::VelocitiesLayer&);
template void draw_pose_layer(PosePanel<Affine3>&, const scene::VelocitiesLayer&);

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::VelocitiesLayer& l) {
  frames(l.samples, "velocities", shape_points() * (kShapeUnits + 2));
}

}  // namespace detail

}  // namespace pita::render
