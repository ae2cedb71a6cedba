// pita eval SCENE.json [--method M] [--samples N | --t T1,T2,...] [--format json|csv]
//
// Evaluates the motion through the keyframes of a scene at sample times and
// prints the frames (JSON or CSV) on stdout.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct EvalOptions {
  std::string scene_path;
  std::optional<std::string> method;   // --method, as typed
  std::optional<std::string> samples;  // --samples, as typed
  std::optional<std::string> times;    // --t, as typed: "0,0.25,1.5"
  std::string format = "json";         // --format: json or csv
  std::optional<int> panel;            // --panel: the motion of this panel (0-based)
};

// Declares the eval subcommand on `app`; app.parse() fills the returned options.
std::shared_ptr<EvalOptions> setup_eval(CLI::App& app);

// Does the work. Prints the frames on stdout, or a message on stderr and
// nothing on stdout.
ExitCode run_eval(const EvalOptions& options);

}  // namespace pita::cli
