// pita check [SCENE...] [--golden DIR] [--report DIR] [tolerances]
// pita update-goldens [SCENE...] [--golden DIR]
//
// check renders each scene in memory and compares it with its goldens
// (golden/check.hpp): exit 0 when all match, 1 when any differs or has no
// golden, 2 on a bad scene or an unreadable golden. update-goldens is the only
// way goldens change: it prints which files changed and by how much.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct GoldenOptions {
  std::vector<std::string> scene_paths;  // default: scenes/*.json
  std::string golden_dir = "golden";
  std::optional<std::string> report_dir;
  double number_tolerance;
  double svg_tolerance;
  int pixel_tolerance;
  double max_differing;
};

std::shared_ptr<GoldenOptions> setup_check(CLI::App& app);
std::shared_ptr<GoldenOptions> setup_update_goldens(CLI::App& app);

ExitCode run_check(const GoldenOptions& options);
ExitCode run_update_goldens(const GoldenOptions& options);

}  // namespace pita::cli
