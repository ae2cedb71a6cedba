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
  // Given on the command line: they override the scene's "golden" field,
  // which overrides the defaults of golden/check.hpp.
  std::optional<double> number_tolerance;
  std::optional<double> svg_tolerance;
  std::optional<int> pixel_tolerance;
  std::optional<double> max_differing;
  std::optional<int> jobs;  // --jobs: scenes worked on at once (cli/scene_jobs.hpp)
};

std::shared_ptr<GoldenOptions> setup_check(CLI::App& app);
std::shared_ptr<GoldenOptions> setup_update_goldens(CLI::App& app);

ExitCode run_check(const GoldenOptions& options);
ExitCode run_update_goldens(const GoldenOptions& options);

}  // namespace pita::cli
