// "measures" in a pose scene: ARA, area monotonicity (or any name of
// scene/measure_name.hpp) of the panel's motion, printed.
#include "analysis/measure.hpp"
#include "render/layers/pose_layers.hpp"
#include "render/measure_text.hpp"

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

}  // namespace pita::render
