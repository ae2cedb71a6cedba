// The "plot" layer: a motion's distance-time function (analysis/distance_time.hpp),
// or with "of": "time" its timing's warp, drawn in a box of the plane, for
// keyframe and pose scenes alike.
#pragma once

#include <string>
#include <vector>

#include "analysis/area_time.hpp"
#include "motion/scene_motion.hpp"
#include "render/drawing.hpp"
#include "scene/figure.hpp"

namespace pita::render {

// The plot's items: its frame, the dashed diagonal of constant speed, the
// curve at `layer.samples` times, a dot at each of `marks` (scene times) when
// the layer asks for them, and the axis names ("of": "time": the warp, the
// share of the motion's own time against that of scene time). Throws
// std::invalid_argument when the tracked point does not move (the distance
// has no unit).
std::vector<Item> plot_items(const scene::PlotLayer& layer, const motion::SceneMotion& motion,
                             const std::vector<double>& marks, const std::string& pointer);

// One curve of an area plot ("of": "area", SAM Fig. 9): a method's name, its
// colour, its area at the plot's samples and at the panel's frame times.
struct AreaSeries {
  std::string name;
  Color color;
  analysis::AreaCurve curve;
  analysis::AreaCurve marks;
};

// The area plot's items: its frame, each series' area against the fraction
// of time, between the smallest and the largest area of all series (printed
// at the axis's ends), the marks when the layer asks for them, and under the
// box one line per series with its measured monotonicity.
std::vector<Item> area_plot_items(const scene::PlotLayer& layer, const std::vector<AreaSeries>& series, double first,
                                  double last, const std::string& pointer);

// The line printed for one series: "SAM: area monotone (falling), end/start = 0.5"
// or "rARAP: area not monotone, largest at t = 0.5 (1.2 x start)".
std::string area_summary(const std::string& name, const analysis::AreaCurve& curve);

}  // namespace pita::render
