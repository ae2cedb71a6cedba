// pita watch SCENE -o OUT [--format LIST] [--scale S | --dpi D] [--at T]
//
// Renders the scene as `pita render` does, then again each time the scene or
// an image it uses is saved (serve/file_watch.hpp), writing every output
// atomically. A save that cannot be rendered prints the error and keeps the
// last good output; Ctrl-C stops (no temporary is left).
#pragma once

#include <memory>

#include "cli/exit_code.hpp"
#include "cli/render.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct WatchOptions {
  RenderOptions render;  // one scene; -o, --format, --scale, --dpi, --budget, --at, --allow-absolute-paths
  int max_renders = 0;   // hidden --max-renders N: stop after N renders (0: never; for tests)
};

std::shared_ptr<WatchOptions> setup_watch(CLI::App& app);

// Exit 2 for bad options or when the scene cannot be watched, 0 after
// --max-renders; otherwise runs until a signal ends it (128 + signal).
ExitCode run_watch(const WatchOptions& options);

}  // namespace pita::cli
