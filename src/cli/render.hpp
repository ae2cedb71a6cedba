// pita render SCENE... -o OUT [--format svg,png,pdf] [--scale S | --dpi D]
//
// Draws each scene's figure (render/figure.hpp) and writes it, through a
// temporary file renamed into place, as OUT (one scene, OUT with an
// extension) or as OUT/<scene name>.<format> for each format.
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

struct RenderOptions {
  std::vector<std::string> scene_paths;
  std::string output;                  // -o: a file (.svg/.png/.pdf) or a directory
  std::optional<std::string> formats;  // --format svg,png,pdf as typed
  std::optional<double> scale;         // --scale (PNG)
  std::optional<double> dpi;           // --dpi (PNG): scale = dpi / 96
  double budget = 1.0;                 // --budget: times the default work budget
  std::optional<double> at;            // --at T: the animation's frame at T (docs/reference/animate.md "Animation")
  std::optional<double> fps;           // --fps, --duration, --frames: the animation's clock, as
  std::optional<double> duration;      // `pita animate` takes them (they space a trail's frames)
  std::optional<int> frames;
  bool allow_absolute_paths = false;  // --allow-absolute-paths: images by absolute paths
  bool list = false;                  // --list: print each scene's name, title and description
  std::optional<int> jobs;            // --jobs: scenes rendered at once (cli/scene_jobs.hpp)
  std::optional<std::string> method;  // --method: the scene's method replaced (as pita eval --method)
};

std::shared_ptr<RenderOptions> setup_render(CLI::App& app);

// Renders every scene, even after one fails; exit 2 if any scene was bad.
// With --list, prints the scenes (the files given, the *.json of the folders
// given, else of ./scenes) with their titles and descriptions instead.
ExitCode run_render(const RenderOptions& options);

// For `pita watch`, which renders one scene again at each save, as render
// does: the problem with the options (what run_render prints after "pita: "
// and exits 2 for), or nullopt.
std::optional<std::string> render_usage_problem(const RenderOptions& options);
// Renders options.scene_paths[0] in every format and writes the files all or
// none; returns the paths written and appends the claims' warnings (lines) to
// `warnings`. Throws what rendering throws (cli/failure.hpp names it).
std::vector<std::string> render_and_write(const RenderOptions& options, std::string& warnings);

}  // namespace pita::cli
