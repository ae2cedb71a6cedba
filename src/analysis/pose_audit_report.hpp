// `pita audit poses`'s outputs as text: the table (Markdown, CSV, JSON), one
// block per dimension (docs/reference/audit.md "What carries over to affine poses").
#pragma once

#include <string>

#include "analysis/audit_report.hpp"
#include "analysis/pose_audit.hpp"

namespace pita::analysis {

std::string format_pose_audit(const PoseAuditReport& report, AuditFormat format);

// How a cell reads in the table: "yes 3.1e-15", "**no** 0.0e+00", "97%" (exists), "no 0.41" (steady: the median
// ARA). `bold` marks a failing verdict with Markdown's **.
std::string pose_cell_text(const PoseAuditCell& cell, bool bold);

}  // namespace pita::analysis
