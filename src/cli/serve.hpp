// pita serve SCENE... [--port N] [--host ADDRESS] (docs/reference/serve.md)
//
// A local page that shows each scene's figure live: re-rendered on each save
// and pushed to the page, with the error of a bad save, a time slider for a
// scene with a motion, and the measures of the scene. The server runs in a
// helper program, pita-serve, beside pita (or in ../libexec/pita/ once
// installed): it links the HTTP library (cpp-httplib, with OpenSSL), whose
// loading would add about 2 ms to every start of pita.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct ServeOptions {
  std::vector<std::string> scene_paths;
  int port = 8765;
  std::string host = "127.0.0.1";
  bool allow_absolute_paths = false;
  bool edit = false;        // --edit: dragging in the page writes into the scene files
  std::string token;        // --token: this token, not a new one
  bool keep_token = false;  // --keep-token: the token kept for the current folder
  bool new_token = false;   // --new-token: a new kept token
  bool open = false;        // --open: the page in the browser (xdg-open)
};

// Adds the options of `pita serve` to `command` (pita's subcommand, and
// pita-serve's own command line).
void add_serve_options(CLI::App& command, ServeOptions& options);

std::shared_ptr<ServeOptions> setup_serve(CLI::App& app);

// Starts pita-serve with these options in place of this process. Returns
// only when it cannot: exit 2 (with the reason) when pita-serve is missing.
ExitCode run_serve(const ServeOptions& options);

}  // namespace pita::cli
