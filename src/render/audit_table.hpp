// PITA Fig. 10 as `pita audit` measured it: a grid of methods (rows) by
// properties (columns), each cell green where the property holds and red
// where it fails, ringed where the paper prints otherwise, and below it the
// paper's "PITAs per property" list beside the measured one.
#pragma once

#include <string>

#include "analysis/audit.hpp"
#include "render/drawing.hpp"
#include "render/figure.hpp"

namespace pita::render {

// The table in world units that are canvas pixels, y down, from (0, 0) to
// (`width`, `height`).
struct PropertyTable {
  Drawing drawing;
  double width = 0.0;
  double height = 0.0;
};
PropertyTable property_table(const analysis::AuditReport& report);

// The figure's bytes (SVG, PNG or PDF; the same report gives the same bytes).
std::string render_property_table(const analysis::AuditReport& report, Format format);

}  // namespace pita::render
