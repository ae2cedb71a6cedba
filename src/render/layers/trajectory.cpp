// "trajectory" in an arrow scene: the path of D(t).p, D(t).q or their midpoint,
// of the panel's motion or of the layer's own method or options.
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::TrajectoryLayer& layer) {
  const std::vector<double> times = layer_times(panel_, layer.samples, layer.range);
  const bool own = layer.method.has_value() || !layer.options.empty();
  const std::vector<Arrow> path = own ? frames(layer_motion(layer.method, layer.options), times) : frames(times);
  std::vector<Point> points;
  points.reserve(path.size());
  for (const Arrow& frame : path) {
    switch (layer.point) {
      case scene::TrackedPoint::start:
        points.push_back(frame.p);
        break;
      case scene::TrackedPoint::end:
        points.push_back(frame.q());
        break;
      case scene::TrackedPoint::middle:
        points.push_back(0.5 * (frame.p + frame.q()));
        break;
    }
  }
  push(-1, Polyline{std::move(points), false, layer.line});
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::TrajectoryLayer& l) {
  add(layer_ + "/samples", fmt::format("{} points of a trajectory", l.samples),
      kShapeUnits + l.samples * motion::frame_cost(panel_));
}

}  // namespace pita::render::detail
