// `pita audit poses` as a figure, in the layout of PITA Fig. 10: per
// dimension, a row per property and a column per pose method, green where
// the property holds and red where it fails, with the number measured (the
// share where the motion exists, the median ARA for steadiness), and the
// section of the paper each row carries over.
#pragma once

#include <string>

#include "analysis/pose_audit.hpp"
#include "render/audit_table.hpp"
#include "render/figure.hpp"

namespace pita::render {

PropertyTable pose_property_table(const analysis::PoseAuditReport& report);

// The figure's bytes (SVG, PNG or PDF; the same report gives the same bytes).
std::string render_pose_property_table(const analysis::PoseAuditReport& report, Format format);

}  // namespace pita::render
