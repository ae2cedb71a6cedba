// "point-trajectory" in a scene of timed points (Sec. 7.6, Fig. 29): the curve
// through the points (the PITA's, or another point curve), with a dot at each.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/limits.hpp"
#include "render/layer_cost.hpp"
#include "render/panel_builder.hpp"

namespace pita::render::detail {

void PanelBuilder::add(const scene::PointTrajectoryLayer& layer) {
  if (points_.empty()) {
    fail(layer_, "a point-trajectory draws a curve through timed \"points\"; this panel has keyframes");
  }
  const double from = layer.range ? layer.range->from : points_.front().t;
  const double to = layer.range ? layer.range->to : points_.back().t;
  std::vector<Point> path;
  path.reserve(static_cast<std::size_t>(layer.samples));
  if (layer.curve == PointCurve::pita) {
    try {
      for (const double t : motion::uniform_times(from, to, layer.samples)) path.push_back(motion_.point_at(t));
    } catch (const motion::NoMotion& error) {
      fail(layer_, error.reason());
    }
  } else {
    std::optional<PointCurveMotion> curve;
    try {
      curve.emplace(motion::point_curve(scene_, panel_, layer.curve));
    } catch (const motion::NoMotion& error) {
      fail(layer_ + "/curve", error.reason());
    }
    for (const double t : motion::uniform_times(from, to, layer.samples)) {
      const Point x = curve->at(t);
      if (!std::isfinite(x.real()) || !std::isfinite(x.imag())) {
        fail(layer_ + "/curve", fmt::format("the {} curve has no finite point at t = {} (its numbers overflow "
                                            "there: knots very uneven, or t far outside them)",
                                            info(layer.curve).name, t));
      }
      path.push_back(x);
    }
  }
  push(-1, Polyline{std::move(path), false, layer.line});
  if (!layer.dots) return;
  // Dots at the timed points, sized by the points' spread.
  Point low = points_.front().p, high = low;
  for (const TimedPoint& point : points_) {
    low = {std::min(low.real(), point.p.real()), std::min(low.imag(), point.p.imag())};
    high = {std::max(high.real(), point.p.real()), std::max(high.imag(), point.p.imag())};
  }
  const double radius = 0.012 * std::max(std::abs(high - low), limits::kTinyScale);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    push(static_cast<int>(i), Circle{points_[i].p, radius, layer.line, layer.line.color});
  }
}

// Its cost (render/layer_cost.hpp).
void LayerCost::operator()(const scene::PointTrajectoryLayer& l) {
  // The Neville-type curves blend n(n - 1)/2 times per point.
  const auto* given = std::get_if<scene::PointKeys>(&panel_.keys);
  const double n = given != nullptr ? static_cast<double>(given->points.size()) : 0.0;
  const double per_point = l.curve == PointCurve::pita ? motion::frame_cost(panel_) : 1.0 + n * (n - 1.0) / 2.0;
  add(layer_ + "/samples", fmt::format("{} points of a point trajectory", l.samples),
      kShapeUnits + l.samples * per_point + (l.dots ? n * kShapeUnits : 0.0));
}

}  // namespace pita::render::detail
