// The "sam3d-existence" layer: a chart drawn without a motion.
#pragma once

#include <string>

#include "analysis/sam3d_existence.hpp"
#include "render/drawing.hpp"
#include "scene/figure.hpp"

namespace pita::render {

// The "sam3d-existence" layer (the SAM paper's Sec. 5.2 experiment as a
// plot): x = theta in [0, pi], y = scene::kSafeCurveScale p. The first
// computes the curve (seconds: analysis/sam3d_existence.hpp), the second
// draws a given one (for tests).
Drawing sam3d_existence_drawing(const scene::Sam3dExistenceLayer& layer, const std::string& pointer);
Drawing sam3d_existence_drawing(const scene::Sam3dExistenceLayer& layer, const analysis::SafeCurve& curve,
                                const std::string& pointer);

}  // namespace pita::render
