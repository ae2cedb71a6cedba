// "vectors" in an arrow scene (Figs. 9, 14, 15): velocities or accelerations
// of D(t).p and D(t).q as arrows.
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

// "vectors" (Figs. 9, 14, 15): scale x dx/du or d2x/du2, u = (t - a)/(c - a).
void PanelBuilder::add(const scene::VectorsLayer& layer) {
  const std::vector<double> times = layer_times(panel_, layer.samples, layer.range);
  const double span = motion_.last() - motion_.first();
  const bool velocity = layer.of == scene::VectorKind::velocity;
  const double factor = layer.scale * (velocity ? span : span * span);
  int index = 0;
  for (const analysis::FrameDerivatives& d : derivatives(times)) {
    const auto vector = [&](Point at, Vector rate, const Color& color) {
      const Vector drawn = factor * rate;
      if (!std::isfinite(drawn.real()) || !std::isfinite(drawn.imag())) {
        fail(layer_, fmt::format("the {} at t = {} is not finite", velocity ? "velocity" : "acceleration", d.t));
      }
      const Point from = layer.tail_at_point ? at : at - drawn;
      const Point to = layer.tail_at_point ? at + drawn : at;
      LineStyle line = layer.line;
      line.color = color;
      if (layer.heads) {
        push(index, ArrowShape{from, to, line});
      } else {
        push(index, Polyline{{from, to}, false, line});
      }
    };
    if (layer.at_p) vector(d.p, velocity ? d.dp : d.ddp, layer.color_p);
    if (layer.at_q) vector(d.q, velocity ? d.dq : d.ddq, layer.color_q);
    ++index;
  }
}

// Its cost (render/layer_cost.hpp).
// Each frame evaluates a stencil of five or six more frames (frame_derivatives).
void LayerCost::operator()(const scene::VectorsLayer& l) { frames(l.samples, "vectors", 7 * kShapeUnits); }

}  // namespace pita::render::detail
