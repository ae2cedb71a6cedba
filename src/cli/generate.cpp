#include "cli/generate.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/completion.hpp"
#include "cli/man_page.hpp"

namespace pita::cli {

std::shared_ptr<GenerateOptions> setup_generate(CLI::App& app) {
  auto options = std::make_shared<GenerateOptions>();
  app.add_option("--generate", options->what, "Print the man page or a shell completion script")
      ->check(CLI::IsMember({"man", "bash", "zsh"}))
      ->group("");  // hidden: for the build, not for users
  return options;
}

ExitCode run_generate(const CLI::App& app, const GenerateOptions& options, std::string_view version) {
  const std::string text = options.what == "man"    ? man_page(app, version)
                           : options.what == "bash" ? bash_completion(app)
                                                    : zsh_completion(app);
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
    std::cerr << "pita: cannot write to standard output (" << std::strerror(errno) << ")\n";
    return ExitCode::failure;
  }
  return ExitCode::success;
}

}  // namespace pita::cli
