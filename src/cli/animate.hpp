// pita animate SCENE -o OUT [--fps F] [--duration S] [--frames N] [--scale S]
//                             [--format png|svg] [--quiet] [--allow-absolute-paths]
//
// Plays a scene (docs/reference/animate.md "Animation"): an animated SVG, a video through
// ffmpeg, or a directory of frames with frames.json (animate/output.hpp).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "cli/exit_code.hpp"

namespace CLI {
class App;
}

namespace pita::cli {

struct AnimateOptions {
  std::string scene_path;
  std::string output;
  std::optional<double> fps;
  std::optional<double> duration;
  std::optional<int> frames;
  double scale = 1.0;
  std::optional<std::string> format;  // directory frames: png (default) or svg
  bool quiet = false;
  bool allow_absolute_paths = false;
  double budget = 1.0;
};

std::shared_ptr<AnimateOptions> setup_animate(CLI::App& app);
ExitCode run_animate(const AnimateOptions& options);

}  // namespace pita::cli
