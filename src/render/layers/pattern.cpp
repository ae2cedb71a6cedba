// "pattern" in an arrow scene: the frames D(t_i) of the panel's motion (or of the
// layer's own method or options) as segments, arrows or dots, each with its
// winding as a coil when asked (Figs. 1-3).
#include <algorithm>
#include <utility>
#include <vector>

#include "render/panel_builder.hpp"
#include "render/spiral.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::PatternLayer& layer) {
  const bool own = layer.method.has_value() || !layer.options.empty();
  // "times": exactly those (an animation frame still draws its own time).
  const std::vector<double> times =
      layer.times.empty() || selection_ != nullptr ? sequence_times(layer.samples, layer.range) : layer.times;
  const std::vector<Arrow> pattern = own ? frames(layer_motion(layer), times) : frames(times);
  // A dot's radius: a fixed share of the first keyframe's magnitude.
  const double dot = 0.015 * std::max(keyframes_.front().arrow.m, 1e-300);
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const Arrow& frame = pattern[i];
    const Segment s = layer.extended ? extended_form(frame) : Segment{frame.p, frame.q()};
    LineStyle line = layer.line;
    line.opacity *= fade(i, pattern.size());
    if (layer.dots) {
      push(static_cast<int>(i), Circle{frame.p, dot, line, line.color});
    } else if (layer.heads) {
      push(static_cast<int>(i), ArrowShape{s.from, s.to, line});
    } else {
      push(static_cast<int>(i), Polyline{{s.from, s.to}, false, line});
    }
    drawing_.items.back().moving = selection_ != nullptr;
    if (!layer.coils) continue;
    // The frame's winding, drawn as the keyframes layer draws A's, B's, C's.
    std::vector<Point> coil = winding_spiral(frame.p, frame.m, frame.w);
    if (coil.empty()) continue;
    push(static_cast<int>(i), Polyline{std::move(coil), false, line});
    drawing_.items.back().moving = selection_ != nullptr;
  }
}

}  // namespace pita::render::detail
