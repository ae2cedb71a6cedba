// The lint's "hidden-copy" check (scene::kLintChecks): a copy of a motion (a
// shape a "shapes" layer carries to a frame, opaque: the faces of a 3D solid)
// that what is painted after it covers by more than "max_hidden_share" of its
// area (SAM 3D Fig. 13: a span's copies behind a control pose drawn over
// them). Measured on a raster of the panel, in the order things are painted.
#pragma once

#include <vector>

#include "lint/geometry.hpp"
#include "lint/lint.hpp"
#include "scene/lint_settings.hpp"

namespace pita::lint {

// The raster's cell, in canvas pixels.
inline constexpr double kOcclusionCell = 2.0;
// A fill at least this opaque hides what is under it; a fainter one does not.
inline constexpr double kOpaqueFill = 0.9;

void hidden_copy(const FigureGeometry& figure, const scene::LintSettings& settings, std::vector<Finding>& findings);

}  // namespace pita::lint
