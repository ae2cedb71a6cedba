// pita lint SCENE... [--format text|json]
//
// The legibility lint of each scene's figure (lint/lint.hpp; docs/reference/lint.md "Lint"):
// the findings on stdout, exit 1 when any is not accepted by the scene.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct LintOptions {
  std::vector<std::string> scene_paths;
  std::string format = "text";  // --format: text or json
};

// Declares the lint subcommand on `app`; app.parse() fills the returned options.
std::shared_ptr<LintOptions> setup_lint(CLI::App& app);

// 0: every finding of every scene accepted; 1: a finding is not; 2: a bad
// scene (named on stderr; the other scenes are still linted); 3: stdout
// could not be written.
ExitCode run_lint(const LintOptions& options);

}  // namespace pita::cli
