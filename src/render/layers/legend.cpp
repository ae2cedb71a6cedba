// "legend" in an arrow scene: the keyframes' colours and knots, the point
// curves, the method and the trajectories drawn, in their colours.
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"
#include "scene/color.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::LegendLayer& layer) {
  Legend legend{layer.corner, layer.size, {}, true, layer_};
  scene::KeyframesLayer colors;  // the colours of the first keyframes layer, else the defaults
  for (const scene::Layer& other : scene::layers_of<scene::Layer>(scene_, panel_).layers) {
    if (const auto* keys = std::get_if<scene::KeyframesLayer>(&other)) {
      colors = *keys;
      break;
    }
  }
  for (std::size_t i = 0; i < keyframes_.size(); ++i) {
    legend.entries.push_back(
        {scene::series_color(colors.colors, i), fmt::format("{}  t = {}", keyframe_name(i), keyframes_[i].t)});
  }
  // A panel of points: one entry per curve drawn, in its colour.
  for (const scene::Layer& other : scene::layers_of<scene::Layer>(scene_, panel_).layers) {
    const auto* curve = std::get_if<scene::PointTrajectoryLayer>(&other);
    if (curve == nullptr || curve->curve == PointCurve::pita) continue;
    legend.entries.push_back({curve->line.color, std::string(info(curve->curve).name)});
  }
  // The method in the colour of the first pattern layer (its frames), else
  // dark grey; after it the trajectories drawn, in their colour and dash.
  // Overlaid patterns (a "label", or their own "method" or "options") get
  // an entry each, named by the label, else by their method; the paths of
  // such methods get none.
  Color method_color{0.2, 0.2, 0.2, 1.0};
  bool pattern_seen = false;
  std::vector<LegendEntry> paths, overlays;
  for (const scene::Layer& other : scene::layers_of<scene::Layer>(scene_, panel_).layers) {
    const auto* pattern = std::get_if<scene::PatternLayer>(&other);
    if (const auto* path = std::get_if<scene::TrajectoryLayer>(&other)) {
      // The path of an overlaid pattern's method (its own "method" or
      // "options") is named by that pattern's entry, in the same colour.
      if (path->method || !path->options.empty()) continue;
      paths.push_back({path->line.color, trajectory_name(path->point), path->line.dash});
    } else if (pattern != nullptr && (!pattern->label.empty() || pattern->method || !pattern->options.empty())) {
      overlays.push_back(
          {pattern->line.color,
           pattern->label.empty() ? method_name(pattern->method.value_or(track_.method)) : pattern->label,
           pattern->line.dash});
    } else if (pattern != nullptr && !pattern_seen) {
      method_color = pattern->line.color;
      pattern_seen = true;
    }
  }
  if (overlays.empty() || pattern_seen) {
    legend.entries.push_back({method_color, method_name(track_.method)});
  }
  legend.entries.insert(legend.entries.end(), overlays.begin(), overlays.end());
  legend.entries.insert(legend.entries.end(), paths.begin(), paths.end());
  drawing_.legends.push_back(std::move(legend));
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::LegendLayer&) { add(layer_, "a legend", 8 * kShapeUnits); }

}  // namespace pita::render::detail
