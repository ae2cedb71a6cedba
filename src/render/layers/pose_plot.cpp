// "plot" in a pose scene: a curve of the panel's motion against time
// (render/plot.hpp), or "of": "area" (SAM Fig. 9, docs/paper-notes.md N48):
// the area of the frames over time under each of the layer's methods.
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/area_time.hpp"
#include "core/pose_method.hpp"
#include "motion/no_motion.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/plot.hpp"

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
      const motion::SceneMotion moving = motion::with_pose_method(panel.scene(), panel.panel(), methods[k]);
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

}  // namespace pita::render
