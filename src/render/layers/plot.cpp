// "plot": a curve of the panel's motion against time (render/time_chart.hpp); in a
// pose scene also "of": "area" (SAM Fig. 9, docs/paper-notes.md N48), the area
// of the frames over time under each of the layer's methods.
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/panel_builder.hpp"
#include "render/time_chart.hpp"

namespace pita::render {

namespace {

void draw_area_plot(PosePanel<Affine2>& panel, const scene::PlotLayer& layer) {
  (void)panel.motion();  // the panel's own motion, or its error, first
  const std::vector<double> marks = panel.times(std::nullopt, std::nullopt);
  const std::vector<double> samples = panel.times(layer.samples, std::nullopt);
  std::vector<PoseMethod> methods = layer.methods;
  if (methods.empty()) methods.push_back(panel.keys().method);
  std::vector<AreaSeries> series;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const PoseMethodInfo& about = info(methods[k]);
    const auto count = static_cast<int>(panel.keys().poses.size());
    if (count < about.min_poses || count > about.max_poses) {
      panel.fail(fmt::format("methods/{}: {} takes {} to {} poses; the panel has {}", k, about.id, about.min_poses,
                             about.max_poses, count));
    }
    try {
      const motion::SceneMotion moving = motion::with_method(panel.scene(), panel.panel(), methods[k]);
      series.push_back({std::string(about.id), layer.colors[k % layer.colors.size()],
                        analysis::area_over_time(moving, samples), analysis::area_over_time(moving, marks)});
    } catch (const motion::NoMotion& error) {
      panel.fail(fmt::format("methods/{}: {}", k, error.reason()));
    }
  }
  panel.append(area_plot_items(layer, series, panel.motion().first(), panel.motion().last(), panel.layer()));
}

}  // namespace

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::PlotLayer& layer) {
  if (layer.of == scene::PlotOf::area) return draw_area_plot(panel, layer);
  const std::vector<double> marks = panel.times(std::nullopt, std::nullopt);
  try {
    panel.append(plot_items(layer, panel.motion(), marks, panel.layer()));
  } catch (const motion::NoMotion& error) {
    panel.fail(error.reason());
  } catch (const std::invalid_argument& error) {
    panel.fail(fmt::format("cannot plot the distance of {}: {}", scene::method_id(panel.panel().keys), error.what()));
  }
}

// In an arrow scene.
namespace detail {

void PanelBuilder::add(const scene::PlotLayer& layer) {
  try {
    for (Item& item : plot_items(layer, motion_, layer_times(panel_, std::nullopt, std::nullopt), layer_)) {
      drawing_.items.push_back(std::move(item));
    }
  } catch (const motion::NoMotion& error) {
    fail(layer_, error.reason());
  } catch (const std::invalid_argument& error) {
    fail(layer_, fmt::format("cannot plot the distance of {}: {}", scene::method_id(panel_.keys), error.what()));
  }
}

}  // namespace detail

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::PlotLayer& l) {
  // An area plot builds and samples one motion per method.
  const double curves =
      l.of == scene::PlotOf::area ? static_cast<double>(std::max<std::size_t>(1, l.methods.size())) : 1.0;
  const double per_point = l.of == scene::PlotOf::area ? motion::frame_cost(panel_) : 1.0;
  add(layer_ + "/samples", fmt::format("{} points of a plot", l.samples),
      8 * kShapeUnits + curves * l.samples * per_point);
  if (l.marks) frames(std::nullopt, "a plot's marks", curves * (kShapeUnits + 8));
}

}  // namespace detail

}  // namespace pita::render
