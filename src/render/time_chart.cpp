#include "render/time_chart.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <utility>

#include <fmt/format.h>

#include "analysis/distance_time.hpp"
#include "motion/sampler.hpp"

namespace pita::render {

namespace {

// A plot's box in world coordinates: `place` maps the unit square onto it,
// `push` collects the layer's items, and the box is framed at once.
class PlotBox {
 public:
  PlotBox(const scene::PlotLayer& layer, const std::string& pointer)
      : low_(layer.box.min),
        width_(layer.box.max.real() - low_.real()),
        height_(layer.box.max.imag() - low_.imag()),
        pointer_(pointer) {
    const LineStyle frame{Color{0.3, 0.3, 0.3, 1.0}, 0.8, 1.0, {}};
    push(-1, Polyline{{place({0, 0}), place({1, 0}), place({1, 1}), place({0, 1})}, true, frame});
  }
  Point place(Point unit) const {
    return Point{low_.real() + unit.real() * width_, low_.imag() + unit.imag() * height_};
  }
  void push(int index, Shape shape) { items_.push_back({pointer_, index, std::move(shape)}); }
  double smaller_side() const { return std::min(width_, height_); }

  // Tick marks at the quarters of the bottom side (time) and, with `left`, of
  // the left side, and the values at the ends: the time axis from t0 to t1,
  // the left one from left->first to left->second.
  void ticks(double t0, double t1, std::optional<std::pair<double, double>> left, double size = 9.0) {
    const LineStyle tick{Color{0.3, 0.3, 0.3, 1.0}, 0.8, 1.0, {}};
    const Color text{0.2, 0.2, 0.2, 1.0};
    for (const double q : {0.25, 0.5, 0.75}) {
      push(-1, Polyline{{place({q, 0.0}), place({q, 0.03})}, false, tick});
      if (left) push(-1, Polyline{{place({0.0, q}), place({0.02, q})}, false, tick});
    }
    push(-1, Label{fmt::format("{:.3g}", t0), place({-0.01, -0.06}), size, text});
    push(-1, Label{fmt::format("{:.3g}", t1), place({0.985, -0.06}), size, text});
    if (left) {
      // Texts larger than the default 9 px start further left, clear of the box.
      const Point wider{-1.2 * std::max(0.0, size - 9.0), 0.0};
      push(-1, Label{fmt::format("{:.3g}", left->first), place({-0.045, 0.0}), size, text, false, wider});
      push(-1, Label{fmt::format("{:.3g}", left->second), place({-0.045, 1.0}), size, text, false, wider});
    }
  }
  std::vector<Item> items() && { return std::move(items_); }

 private:
  Point low_;
  double width_, height_;
  std::string pointer_;
  std::vector<Item> items_;
};

}  // namespace

namespace {

// The curve of a plot at `times`, in the unit square: the distance-time
// function, or with "of": "time" the timing's warp itself, the share of the
// motion's own time reached at each share of scene time.
std::vector<Point> plotted(const scene::PlotLayer& layer, const motion::SceneMotion& motion,
                           std::span<const double> times) {
  if (layer.of != scene::PlotOf::time) return analysis::distance_time(motion, layer.point, times);
  const double first = motion.first(), duration = motion.last() - motion.first();
  std::vector<Point> curve;
  curve.reserve(times.size());
  for (const double t : times) curve.push_back({(t - first) / duration, (motion.motion_time(t) - first) / duration});
  return curve;
}

}  // namespace

std::vector<Item> plot_items(const scene::PlotLayer& layer, const motion::SceneMotion& motion,
                             const std::vector<double>& marks, const std::string& pointer) {
  PlotBox box(layer, pointer);
  const auto place = [&box](Point unit) { return box.place(unit); };
  const auto push = [&box](int index, Shape shape) { box.push(index, std::move(shape)); };
  push(-1, Polyline{{place({0, 0}), place({1, 1})}, false, LineStyle{Color{0.6, 0.6, 0.6, 1.0}, 0.8, 1.0, {4.0, 3.0}}});

  const std::vector<double> times = motion::uniform_times(motion.first(), motion.last(), layer.samples);
  std::vector<Point> curve;
  for (const Point p : plotted(layer, motion, times)) curve.push_back(place(p));
  push(-1, Polyline{std::move(curve), false, layer.line});

  if (layer.marks) {
    const std::vector<Point> dots = plotted(layer, motion, marks);
    const double radius = 0.015 * box.smaller_side();
    for (std::size_t i = 0; i < dots.size(); ++i) {
      push(static_cast<int>(i),
           Circle{place(dots[i]), radius, LineStyle{layer.line.color, 0.8, 1.0, {}}, layer.line.color});
    }
  }
  const Color text{0.2, 0.2, 0.2, 1.0};
  // The distance is a share of the path's length, the warped time one of the knots' range.
  box.ticks(motion.first(), motion.last(), std::pair{0.0, 1.0}, layer.size - 1.0);
  push(-1, Label{"time", place({0.45, -0.12}), layer.size, text});
  push(-1, Label{layer.of == scene::PlotOf::time ? "motion time" : "distance", place({-0.02, 1.08}), layer.size, text});
  return std::move(box).items();
}

std::string area_summary(const std::string& name, const analysis::AreaCurve& curve) {
  const double start = curve.areas.front(), end = curve.areas.back();
  if (curve.stats.monotone) {
    return fmt::format("{}: area monotone ({}), end/start = {:.4g}", name, end >= start ? "rising" : "falling",
                       end / start);
  }
  // The interior extremum: the largest area when it exceeds both ends, else the smallest.
  const bool bump = curve.largest > std::max(start, end);
  return fmt::format("{}: area not monotone, {} at t = {:.3g} ({:.4g} x start)", name, bump ? "largest" : "smallest",
                     bump ? curve.t_of_largest : curve.t_of_smallest, (bump ? curve.largest : curve.smallest) / start);
}

std::vector<Item> area_plot_items(const scene::PlotLayer& layer, const std::vector<AreaSeries>& series, double first,
                                  double last, const std::string& pointer) {
  PlotBox box(layer, pointer);
  const auto place = [&box](Point unit) { return box.place(unit); };
  const auto push = [&box](int index, Shape shape) { box.push(index, std::move(shape)); };

  double smallest = series.front().curve.smallest, largest = series.front().curve.largest;
  for (const AreaSeries& one : series) {
    smallest = std::min(smallest, one.curve.smallest);
    largest = std::max(largest, one.curve.largest);
  }
  // A constant area (an area-preserving SAM) is drawn at mid-height.
  const double span = largest - smallest;
  const auto unit = [&](double t, double area) {
    const double y = span > 1e-12 * largest ? (area - smallest) / span : 0.5;
    return place({(t - first) / (last - first), y});
  };
  const Color text{0.2, 0.2, 0.2, 1.0};
  for (std::size_t k = 0; k < series.size(); ++k) {
    const AreaSeries& one = series[k];
    LineStyle line = layer.line;
    line.color = one.color;
    std::vector<Point> curve;
    for (std::size_t i = 0; i < one.curve.times.size(); ++i)
      curve.push_back(unit(one.curve.times[i], one.curve.areas[i]));
    push(-1, Polyline{std::move(curve), false, line});
    if (layer.marks) {
      const double radius = 0.012 * box.smaller_side();
      for (std::size_t i = 0; i < one.marks.times.size(); ++i) {
        push(static_cast<int>(i), Circle{unit(one.marks.times[i], one.marks.areas[i]), radius,
                                         LineStyle{one.color, 0.8, 1.0, {}}, one.color});
      }
    }
    push(-1,
         Label{area_summary(one.name, one.curve), place({0.0, -0.2 - 0.1 * static_cast<double>(k)}), 11.0, one.color});
  }
  box.ticks(first, last, std::nullopt, layer.size - 1.0);
  push(-1, Label{"time", place({0.45, -0.08}), layer.size, text});
  push(-1, Label{fmt::format("|det L| = {:.4g}", largest), place({0.01, 1.05}), layer.size, text});
  push(-1, Label{fmt::format("|det L| = {:.4g}", smallest), place({0.01, 0.04}), layer.size, text});
  return std::move(box).items();
}

}  // namespace pita::render
