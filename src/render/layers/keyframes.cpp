// "keyframes" in an arrow scene: the keyframes as arrows, each winding as a
// spiral whose radius grows while it turns through w.
#include <utility>
#include <vector>

#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"
#include "render/spiral.hpp"
#include "scene/color.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::KeyframesLayer& layer) {
  for (std::size_t i = 0; i < keyframes_.size(); ++i) {
    const Arrow& key = keyframes_[i].arrow;
    const Color color = scene::series_color(layer.colors, i);
    const LineStyle line{color, layer.width, layer.opacity, {}};
    if (layer.winding) {
      const Point center = layer.spiral_center == scene::SpiralCenter::start ? key.p : 0.5 * (key.p + key.q());
      std::vector<Point> coil = winding_spiral(center, key.m, key.w);
      if (!coil.empty()) {
        push(static_cast<int>(i),
             Polyline{std::move(coil), false, LineStyle{color, 0.6 * layer.width, layer.opacity, {}}});
      }
    }
    const Segment s = layer.extended ? extended_form(key) : Segment{key.p, key.q()};
    push(static_cast<int>(i), ArrowShape{s.from, s.to, line});
  }
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::KeyframesLayer&) {
  double units = 0.0;
  for (const Keyframe& key : keyframes()) {
    const double turns = std::abs(key.arrow.w) / (2.0 * std::numbers::pi);
    units += 4 * kShapeUnits + std::min(turns * kSpiralPointsPerTurn + 9.0, static_cast<double>(kMaxSpiralPoints));
  }
  add(layer_, "keyframe arrows and winding spirals", units);
}

}  // namespace pita::render::detail
