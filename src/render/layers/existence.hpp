// The "existence" layer: a chart drawn without a motion (render/layers/ holds
// one file per layer kind whose drawing stands alone).
#pragma once

#include <numbers>
#include <string>

#include "render/drawing.hpp"
#include "scene/figure.hpp"

namespace pita::render {

// The "existence" layer alone (Fig. 6 of the SAM paper): exposed for tests.
// Cells are rectangles [a0, a1] x [h s0, h s1] with h = kExistenceHeight.
inline constexpr double kExistenceHeight = std::numbers::pi;  // drawn height of s in [0, 1]
Drawing existence_drawing(const scene::ExistenceLayer& layer, const std::string& pointer);

}  // namespace pita::render
