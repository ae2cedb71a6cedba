// "stroke" in an arrow scene (Sec. 7.2): the quads between consecutive frames,
// filled as one path, and their outline.
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"
#include "render/strip.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::StrokeLayer& layer) {
  const std::vector<Arrow> pattern = frames(layer_times(panel_, layer.samples, layer.range));
  const QuadStrip strip(pattern);
  // One path of quads, each oriented counter-clockwise, filled with the
  // nonzero rule: overlapping quads stay filled and no seams show between
  // neighbours (as separately filled quads would show with antialiasing).
  FilledPath quads{{}, layer.fill, layer.opacity, std::nullopt};
  for (int i = 0; i < strip.quad_count(); ++i) {
    const auto corners = strip.quad(i);
    std::vector<Point> contour(corners.begin(), corners.end());
    turn_counter_clockwise(contour);
    quads.contours.push_back(std::move(contour));
  }
  push(-1, std::move(quads));
  if (layer.outline) {
    std::vector<Point> boundary;
    for (const Arrow& frame : pattern) boundary.push_back(frame.p);
    for (auto it = pattern.rbegin(); it != pattern.rend(); ++it) boundary.push_back(it->q());
    push(-1, Polyline{std::move(boundary), true, *layer.outline});
  }
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::StrokeLayer& l) { frames(l.samples, "a stroke", kShapeUnits + 4); }

}  // namespace pita::render::detail
