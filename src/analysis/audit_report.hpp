// `pita audit`'s outputs as text: the table (Markdown, CSV, JSON) and, for
// each cell that fails, a scene that reproduces the violation with
// `pita eval` (panel 0: the original keyframes; panel 1: the transformed,
// swapped or tweaked counterpart) and draws the two side by side.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "analysis/audit.hpp"

namespace pita::analysis {

enum class AuditFormat { md, csv, json };

// `counterexamples[i]` is the file written for report.cells[i], or empty.
std::string format_audit(const AuditReport& report, AuditFormat format,
                         const std::vector<std::string>& counterexamples = {});

// The file name of a cell's counterexample: "P5-similarity-invariant.json".
std::string counterexample_name(const AuditCell& cell);

// The counterexample scene of a failing cell, as JSON text (docs/reference/audit.md "pita
// audit" says how to replay it). Empty for a cell that holds.
std::string counterexample_scene(const AuditReport& report, const AuditCell& cell);

}  // namespace pita::analysis
