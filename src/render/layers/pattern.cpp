// "pattern" in an arrow scene: the frames D(t_i) of the panel's motion (or of the
// layer's own method or options) as segments, arrows or dots, each with its
// winding as a coil when asked (Figs. 1-3).
#include <algorithm>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/limits.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"
#include "render/spiral.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::PatternLayer& layer) {
  const bool own = layer.method.has_value() || !layer.options.empty();
  // "times": exactly those, fixed, in the figure and in every animation frame
  // alike (as a "shapes" layer's); otherwise the samples, or the animation's
  // moving frame and its trail.
  const bool moving = selection() != nullptr && layer.times.empty();
  const std::vector<double> times = layer.times.empty() ? sequence_times(layer.samples, layer.range) : layer.times;
  const std::vector<Arrow> pattern = own ? frames(layer_motion(layer.method, layer.options), times) : frames(times);
  // A dot's radius: a fixed share of the first keyframe's magnitude.
  const double dot = 0.015 * std::max(keyframes_.front().arrow.m, limits::kTinyScale);
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const Arrow& frame = pattern[i];
    const Segment s = layer.extended ? extended_form(frame) : Segment{frame.p, frame.q()};
    LineStyle line = layer.line;
    if (moving) line.opacity *= fade(i, pattern.size());
    if (layer.dots) {
      push(static_cast<int>(i), Circle{frame.p, dot, line, line.color});
    } else if (layer.heads) {
      push(static_cast<int>(i), ArrowShape{s.from, s.to, line});
    } else {
      push(static_cast<int>(i), Polyline{{s.from, s.to}, false, line});
    }
    drawing_.items.back().moving = moving;
    if (!layer.coils) continue;
    // The frame's winding, drawn as the keyframes layer draws A's, B's, C's.
    std::vector<Point> coil = winding_spiral(frame.p, frame.m, frame.w);
    if (coil.empty()) continue;
    push(static_cast<int>(i), Polyline{std::move(coil), false, line});
    drawing_.items.back().moving = moving;
  }
}

// Its cost (render/layer_cost.hpp).
// ------------------------------------------------------------ arrow layers
void LayerCost::operator()(const scene::PatternLayer& l) {
  double per_frame = kShapeUnits + 2;
  if (l.coils) {
    // A coil per frame: its turns bounded by the keyframes' largest winding,
    // scaled by how far the range reaches beyond the knots, plus one turn.
    double w = 0.0;
    for (const Keyframe& key : keyframes()) w = std::max(w, std::abs(key.arrow.w));
    const double span = keyframes().empty() ? 0.0 : keyframes().back().t - keyframes().front().t;
    const double reach = l.range && span > 0.0 ? std::max(1.0, (l.range->to - l.range->from) / span) : 1.0;
    const double turns = w * reach / (2.0 * std::numbers::pi) + 1.0;
    per_frame += kShapeUnits + std::min(turns * kSpiralPointsPerTurn + 9.0, static_cast<double>(kMaxSpiralPoints));
  }
  if (!l.times.empty()) {  // exactly these frames, not samples over a range
    add(layer_ + "/times", fmt::format("{} frames of a pattern", l.times.size()),
        static_cast<double>(l.times.size()) * (per_frame + motion::frame_cost(panel_) - 1.0));
    return;
  }
  frames(l.samples, "a pattern", per_frame);
}

}  // namespace pita::render::detail
