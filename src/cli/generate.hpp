// pita --generate man|bash|zsh: a hidden option (not in --help) that prints
// the man page or a shell completion script, generated from the App itself.
// src/CMakeLists.txt runs it each time pita is linked, writing build/pita.1,
// build/completions/pita and build/completions/_pita, which are installed.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct GenerateOptions {
  std::string what;  // "man", "bash", "zsh"; empty when not asked
};

// Declares the hidden --generate option on `app`.
std::shared_ptr<GenerateOptions> setup_generate(CLI::App& app);

// Prints what was asked on stdout (exit 3 if it cannot be written).
ExitCode run_generate(const CLI::App& app, const GenerateOptions& options, std::string_view version);

}  // namespace pita::cli
