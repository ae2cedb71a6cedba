// pita sweep SCENE --vary POINTER=SPEC [--vary ...] [--zip] -o DIR
//            [--format svg,png,pdf,csv,json] [--jobs J] [--shard K/N] [--force] [--quiet]
// pita sweep --merge DIR
//
// The front end of src/sweep (docs/reference/sweep.md "pita sweep").
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

struct SweepCommand {
  std::optional<std::string> scene_path;
  std::vector<std::string> vary;
  bool zip = false;
  std::optional<std::string> output;
  std::string formats = "svg";
  std::optional<int> jobs;
  std::optional<std::string> shard;
  std::optional<std::string> merge;
  bool force = false;
  bool wait = false;
  bool quiet = false;
};

std::shared_ptr<SweepCommand> setup_sweep(CLI::App& app);

// 0 every variant written (or resumed), 1 some failed (listed on stderr) or,
// for --merge, some are missing, 2 bad usage or a bad base scene, 3 an output
// could not be written.
ExitCode run_sweep_command(const SweepCommand& command);

}  // namespace pita::cli
