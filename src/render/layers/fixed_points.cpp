// "fixed-points" in an arrow scene (Fig. 9): segments from a point of D(t) to
// P7's global fixed point or to the instantaneous center at t.
#include <algorithm>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/limits.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

// "fixed-points" (Fig. 9): segments from D(t).p (q, mid) to P7's global
// fixed point or to the instantaneous center at t (core/instant_center.hpp).
void PanelBuilder::add(const scene::FixedPointsLayer& layer) {
  const std::vector<double> times = layer_times(panel_, layer.samples, layer.range);
  std::optional<Point> global;
  if (layer.center == scene::CenterKind::global) {
    if (track_.method != Method::P7 || motion_.chain()) {
      fail(layer_ + "/center", fmt::format("\"global\" is P7's fixed point (PITA Eq. 35-36); the panel's method is {}: "
                                           "use \"acceleration\" or \"velocity\" (instantaneous centers)",
                                           motion::method_label(scene_, panel_)));
    }
    global = motion_.arrows().global_fixed_point();
    // f at infinity (P7 degenerate to P1's parabola): nothing to draw.
    if (!global) return;
  }
  const double dot = 0.025 * std::max(keyframes_.front().arrow.m, limits::kTinyScale);
  int index = 0;
  for (const analysis::FrameDerivatives& d : derivatives(times)) {
    std::optional<Point> center = global;
    if (layer.center == scene::CenterKind::acceleration) center = analysis::acceleration_center(d);
    if (layer.center == scene::CenterKind::velocity) center = analysis::velocity_center(d);
    if (center) {
      const Point from = layer.point == scene::TrackedPoint::start ? d.p
                         : layer.point == scene::TrackedPoint::end ? d.q
                                                                   : 0.5 * (d.p + d.q);
      push(index, Polyline{{from, *center}, false, layer.line});
      if (layer.dots && (!global || index == 0)) {
        push(index, Circle{*center, dot, layer.line, layer.line.color});
      }
    }
    ++index;
  }
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::FixedPointsLayer& l) {
  frames(l.samples, "fixed-point segments", 7 * kShapeUnits);
}

}  // namespace pita::render::detail
