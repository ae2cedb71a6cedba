// "discrepancy" in an arrow scene (Sec. 6.2, Fig. 17): circles of radius
// scale E(D(t_i), prediction) around D(t_i).p (PITA Eq. 47 as corrected,
// docs/paper-notes.md N5).
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "analysis/prediction.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::DiscrepancyLayer& layer) {
  const std::vector<double> times = layer_times(panel_, layer.samples, std::nullopt);
  const std::vector<Arrow> pattern = frames(times);
  const Method method = layer.method.value_or(track_.method);
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    std::optional<double> discrepancy;
    try {
      discrepancy = analysis::frame_discrepancy(layer.predictor, method, track_.options, times, pattern, i);
    } catch (const std::exception& error) {
      fail(layer_, fmt::format("cannot predict the frame at t = {}: {}", times[i], error.what()));
    }
    if (!discrepancy) continue;
    const double radius = layer.scale * *discrepancy;
    if (!std::isfinite(radius)) {
      fail(layer_, fmt::format("the discrepancy at t = {} is not finite", times[i]));
    }
    push(static_cast<int>(i), Circle{pattern[i].p, radius, layer.line, layer.fill});
  }
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::DiscrepancyLayer& l) {
  frames(l.samples, "discrepancy circles", kShapeUnits + 8);
}

}  // namespace pita::render::detail
