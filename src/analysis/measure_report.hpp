// The reports of `pita measure` (docs/reference/measure.md "pita measure"):
// the measures of every panel of a scene (analysis/measure.hpp) as JSON, CSV
// or a Markdown table. The CLI prints them; the Python module reads the JSON.
#pragma once

#include <string>
#include <vector>

#include "analysis/measure.hpp"

namespace pita::analysis {

// {"scene": PATH, "motions": [{"pointer", "title", "method", "kind", ...}, ...]}
// with one motion per panel; numbers in their shortest round-trip form.
std::string measures_json(const std::string& scene_path, const std::vector<MotionMeasures>& all);

// A header, then one row per panel; a gain_<parameter> column for every
// keyframe parameter of any panel.
std::string measures_csv(const std::vector<MotionMeasures>& all);

// The Markdown tables people read.
std::string measures_markdown(const std::string& scene_path, const std::vector<MotionMeasures>& all);

}  // namespace pita::analysis
