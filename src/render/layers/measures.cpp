// "measures": numbers of the panel's motion, printed (scene/measure_name.hpp):
// in a pose scene ARA and area monotonicity; in an arrow scene discrepancy,
// paths, overreaction and pops, and comparisons with another method.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/comparison.hpp"
#include "analysis/frame_steps.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/measure_text.hpp"
#include "render/panel_builder.hpp"

namespace pita::render {

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::MeasuresLayer& layer) {
  if (panel.selection() != nullptr) return;  // a figure's numbers, not an animation frame's
  (void)panel.motion();                      // the panel's poses must give a motion (its error otherwise)
  const analysis::MotionMeasures measures = analysis::measure_panel(panel.stage(), panel.index());
  if (measures.no_motion) panel.fail(*measures.no_motion);
  Drawing text;
  add_measure_text(layer, measure_lines(measures, layer.show), text, panel.layer());
  panel.append(std::move(text.items));
}

// In an arrow scene.
namespace detail {

// "measures": the numbers of `pita measure` for this panel's motion.
void PanelBuilder::add(const scene::MeasuresLayer& layer) {
  if (selection() != nullptr) return;  // a figure's numbers, not an animation frame's
  // "angle:M@t" and "handle-shift" compare with another motion, and
  // "knot-distance" with the keyframes (analysis/comparison.hpp); the others
  // are `pita measure`'s.
  std::vector<std::string> lines(layer.show.size());
  std::vector<scene::MeasureName> others;
  std::optional<analysis::FrameSteps> steps;  // computed once for the four that read them
  for (std::size_t i = 0; i < layer.show.size(); ++i) {
    const scene::MeasureName& name = layer.show[i];
    const std::string at = layer_ + "/show/" + std::to_string(i);
    try {
      if (name.kind == scene::MeasureKind::handle_shift) {
        if (scene::outlines_of(panel_).empty()) {
          fail(at,
               "\"handle-shift\" measures how far the panel's shapes land, and the panel has no shapes: "
               "give the scene or the panel \"shapes\" (docs/reference/render.md \"Figure fields of a scene\")");
        }
        lines[i] = fmt::format("handle shift: {}", rounding_or_value(analysis::handle_shift(stage_, index_)));
      } else if (name.kind == scene::MeasureKind::angle) {
        const double angle = analysis::vector_angle(stage_, index_, name.method, name.t);
        if (!std::isfinite(angle)) {
          fail(at, fmt::format("the angle at t = {} is undefined: the frame vector of {} or of {} vanishes there",
                               name.t, scene::method_id(panel_.keys), entry_of(name.method).id));
        }
        lines[i] =
            fmt::format("angle {}, {} at t = {}: {} rad", scene::method_id(panel_.keys), entry_of(name.method).id,
                        name.text.substr(name.text.find('@') + 1), rounding_or_value(angle));
      } else if (name.kind == scene::MeasureKind::knot_distance) {
        lines[i] = fmt::format("knot distance: {}", rounding_or_value(analysis::knot_distance(stage_, index_)));
      } else if (analysis::is_frame_step(name.kind)) {  // "scale-step", ...
        if (!steps) steps = analysis::frame_steps(stage_, index_);
        lines[i] = fmt::format("{}: {}{}", name.text, rounding_or_value(*analysis::frame_step(*steps, name.kind)),
                               name.kind == scene::MeasureKind::turn_step ? " rad" : "");
      } else {
        others.push_back(name);
      }
    } catch (const motion::NoMotion& error) {
      fail(layer_, error.reason());
    }
  }
  if (!others.empty()) {
    const analysis::MotionMeasures measures = analysis::measure_panel(stage_, index_);
    if (measures.no_motion) fail(layer_, *measures.no_motion);
    const std::vector<std::string> measured = measure_lines(measures, others);
    for (std::size_t i = 0, k = 0; i < lines.size(); ++i) {
      if (lines[i].empty()) lines[i] = measured[k++];
    }
  }
  add_measure_text(layer, lines, drawing_, layer_);
}

}  // namespace detail

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::MeasuresLayer&) {
  add(layer_, "the measures of the motion", 8 * kShapeUnits + analysis::measure_cost(panel_));
}

}  // namespace detail

}  // namespace pita::render
