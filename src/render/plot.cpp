#include "render/plot.hpp"

#include "analysis/distance_time.hpp"
#include "motion/sampler.hpp"

namespace pita::render {

std::vector<Item> plot_items(const scene::PlotLayer& layer, const motion::SceneMotion& motion,
                             const std::vector<double>& marks, const std::string& pointer) {
  const Point low = layer.box.min, high = layer.box.max;
  const double width = high.real() - low.real(), height = high.imag() - low.imag();
  const auto place = [&](Point unit) {
    return Point{low.real() + unit.real() * width, low.imag() + unit.imag() * height};
  };
  std::vector<Item> items;
  const auto push = [&](int index, Shape shape) { items.push_back({pointer, index, std::move(shape)}); };

  const LineStyle frame{Color{0.3, 0.3, 0.3, 1.0}, 0.8, 1.0, {}};
  push(-1, Polyline{{place({0, 0}), place({1, 0}), place({1, 1}), place({0, 1})}, true, frame});
  push(-1, Polyline{{place({0, 0}), place({1, 1})}, false,
                    LineStyle{Color{0.6, 0.6, 0.6, 1.0}, 0.8, 1.0, {4.0, 3.0}}});

  const std::vector<double> times = motion::uniform_times(motion.first(), motion.last(), layer.samples);
  std::vector<Point> curve;
  for (const Point p : analysis::distance_time(motion, layer.point, times)) curve.push_back(place(p));
  push(-1, Polyline{std::move(curve), false, layer.line});

  if (layer.marks) {
    const std::vector<Point> dots = analysis::distance_time(motion, layer.point, marks);
    const double radius = 0.015 * std::min(width, height);
    for (std::size_t i = 0; i < dots.size(); ++i) {
      push(static_cast<int>(i), Circle{place(dots[i]), radius, LineStyle{layer.line.color, 0.8, 1.0, {}},
                                       layer.line.color});
    }
  }
  const Color text{0.2, 0.2, 0.2, 1.0};
  push(-1, Label{"time", place({0.5, -0.12}), 10.0, text});
  push(-1, Label{"distance", place({-0.02, 1.08}), 10.0, text});
  return items;
}

}  // namespace pita::render
