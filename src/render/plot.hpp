// The "plot" layer: a motion's distance-time function (analysis/distance_time.hpp)
// drawn in a box of the plane, for keyframe and pose scenes alike.
#pragma once

#include <string>
#include <vector>

#include "motion/scene_motion.hpp"
#include "render/drawing.hpp"
#include "scene/figure.hpp"

namespace pita::render {

// The plot's items: its frame, the dashed diagonal of constant speed, the
// curve at `layer.samples` times, a dot at each of `marks` (scene times) when
// the layer asks for them, and the axis names. Throws std::invalid_argument
// when the tracked point does not move (the distance has no unit).
std::vector<Item> plot_items(const scene::PlotLayer& layer, const motion::SceneMotion& motion,
                             const std::vector<double>& marks, const std::string& pointer);

}  // namespace pita::render
