// pita measure SCENE.json [--format md|csv|json]
//
// Prints the goodness measures of the scene's motion, or of each panel's
// (analysis/measure.hpp; docs/reference/measure.md "pita measure"), on stdout.
#pragma once

#include <memory>
#include <string>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct MeasureOptions {
  std::string scene_path;
  std::string format = "md";  // --format: md, csv or json
};

// Declares the measure subcommand on `app`; app.parse() fills the returned options.
std::shared_ptr<MeasureOptions> setup_measure(CLI::App& app);

// Does the work: the whole report on stdout, or a message on stderr and
// nothing on stdout (exit 2 for a bad scene).
ExitCode run_measure(const MeasureOptions& options);

}  // namespace pita::cli
