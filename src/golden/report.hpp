// The report of `pita check --report DIR`: for each scene whose outputs
// differ from their goldens, the expected, actual and diff images, and one
// index.html that shows them side by side with the numbers (a CI artifact).
#pragma once

#include <filesystem>
#include <vector>

#include "golden/check.hpp"

namespace pita::golden {

// Writes DIR/index.html and, per differing scene, DIR/<name>.expected.png,
// DIR/<name>.actual.png, DIR/<name>.diff.png (and the SVGs). Scenes that
// could not be checked are listed with their error. Throws
// std::runtime_error when a file cannot be written.
struct ReportEntry {
  SceneCheck check;
  std::string error;  // non-empty: the scene could not be checked (bad scene or golden)
};
// A file of the report that would replace one of `inputs` (the scenes, their
// images and goldens: `--report golden/x` when a scene is named x.actual) is
// refused before anything is written: GoldenError naming both.
void write_report(const std::filesystem::path& dir, const std::vector<ReportEntry>& entries,
                  const std::vector<std::filesystem::path>& inputs);

}  // namespace pita::golden
