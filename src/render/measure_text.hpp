// The text of a "measures" layer: the numbers of `pita measure`
// (analysis/measure.hpp) as short lines, one per name the layer shows.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "analysis/measure.hpp"
#include "render/drawing.hpp"
#include "scene/figure.hpp"

namespace pita::render {

// A printed comparison: a value below 1e-12 in magnitude is rounding noise,
// whose digits differ between compilers, so it is printed as "< 1e-12".
std::string rounding_or_value(double value);

// One line per name of `show` (scene::MeasuresLayer::show), for example
//   "pop: C.p.y jumps 0.83 (x extent)"  or  "pop: none (largest jump 2.1e-09)"
//   "gain B.q: 1.36"                    (the larger of B.q.x and B.q.y)
//   "turn B.q: 12.5 rad"                (orientation change per unit tweak)
// A number the motion lacks gives "ARA: -" (the reader refuses names the
// scene's kind does not measure, scene/measure_name.hpp); "handle-shift" and
// "angle:M@t" compare with another motion and are the panel drawing's.
std::vector<std::string> measure_lines(const analysis::MotionMeasures& measures,
                                       std::span<const scene::MeasureName> show);

// Adds the lines to the drawing as the layer places them: one label (lines
// joined) at the layer's world point, else a text-only legend in its corner.
void add_measure_text(const scene::MeasuresLayer& layer, const std::vector<std::string>& lines, Drawing& drawing,
                      const std::string& layer_pointer);

}  // namespace pita::render
