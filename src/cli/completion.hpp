// Shell completion for bash and zsh: generated when pita is built
// (`pita --generate bash|zsh`, src/CMakeLists.txt) from the CLI11 App that
// --help prints (cli/command_line.hpp): subcommands, flags, method names of
// the registry for --method and --methods, the choices of --format, scene
// files (*.json) for SCENE, directories and files where an option takes them.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace pita::cli {

// A bash script defining _pita and `complete -F _pita pita`
// (share/bash-completion/completions/pita).
std::string bash_completion(const CLI::App& app);

// A zsh completion function, `#compdef pita` (share/zsh/vendor-completions/_pita).
std::string zsh_completion(const CLI::App& app);

}  // namespace pita::cli
