#include "cli/watch.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/failure.hpp"
#include "render/figure.hpp"
#include "scene/image_file.hpp"
#include "scene/scene.hpp"
#include "serve/file_watch.hpp"

namespace pita::cli {

namespace {

namespace fs = std::filesystem;

// The files a render of the scene read: the scene, and its images when it
// could be read (else those of the last scene that could).
std::vector<fs::path> watched_files(const RenderOptions& options, std::vector<fs::path>& images) {
  try {
    images = scene::image_files(
        scene::load_scene(options.scene_paths.front(), {options.allow_absolute_paths, std::nullopt}));
  } catch (...) {
    // a bad save: keep the images of the last good one
  }
  std::vector<fs::path> files{options.scene_paths.front()};
  files.insert(files.end(), images.begin(), images.end());
  return files;
}

// One render; false when it failed (the error is printed, the outputs kept).
bool render(const RenderOptions& options) {
  try {
    std::string warnings;
    const std::vector<std::string> written = render_and_write(options, warnings);
    std::cerr << warnings;
    for (const std::string& file : written) std::cout << "wrote " << file << '\n';
    std::cout.flush();
    return true;
  } catch (...) {
    const Failure failure = current_failure(options.scene_paths.front());
    std::cerr << "pita: " << failure.message << "\npita: the last good output is kept; waiting for the next save\n";
    return false;
  }
}

}  // namespace

std::shared_ptr<WatchOptions> setup_watch(CLI::App& app) {
  auto options = std::make_shared<WatchOptions>();
  CLI::App* watch =
      app.add_subcommand("watch", "Render a scene, then again each time it (or an image it uses) is saved");
  watch->footer(R"(
Renders SCENE as `pita render SCENE -o OUT` does, then waits: each save of the scene file, or of
an image its shapes use, renders it again (inotify; a burst of saves is one render). Every output
is written through a temporary renamed into place, so OUT is always a whole figure. A save that
cannot be rendered (malformed JSON, a bad value, no motion) prints the error, with the file,
line:column or JSON Pointer, and keeps the last good output; the next good save replaces it.
Ctrl-C (or SIGTERM) stops it and removes any output being written.

Examples:
  pita watch scenes/fig01-eight-pitas.json -o fig01.svg
  pita watch my-scene.json -o out --format svg,png

Exit codes: 2 bad input or usage (a bad scene does not end it: the error is printed and it
waits); 128 + N when signal N ends it.
)");
  watch->add_option("SCENE", options->render.scene_paths, "Scene file (JSON)")->required()->expected(1);
  watch->add_option("-o,--output", options->render.output, "Output file (.svg/.png/.pdf) or directory")
      ->required()
      ->type_name("OUT");
  watch
      ->add_option_function<std::string>(
          "--format", [options](const std::string& list) { options->render.formats = list; },
          "Formats to write into the OUT directory, comma-separated: svg,png,pdf (default svg)")
      ->type_name("LIST");
  CLI::Option* scale =
      watch
          ->add_option_function<double>(
              "--scale", [options](double s) { options->render.scale = s; },
              fmt::format("PNG pixels per canvas pixel ({} to {}; default 1)", render::kMinScale, render::kMaxScale))
          ->type_name("S");
  CLI::Option* dpi =
      watch
          ->add_option_function<double>(
              "--dpi", [options](double d) { options->render.dpi = d; }, "PNG resolution: scale = DPI / 96")
          ->type_name("DPI");
  scale->excludes(dpi);
  watch
      ->add_option_function<double>(
          "--at", [options](double t) { options->render.at = t; },
          "Draw the scene's animation at time T, as `pita render --at`")
      ->type_name("T");
  watch->add_flag("--allow-absolute-paths", options->render.allow_absolute_paths,
                  "Allow images given by absolute paths");
  watch->add_option("--max-renders", options->max_renders, "Stop after N renders (tests)")
      ->group("")
      ->check(CLI::Range(0, 1000000));
  return options;
}

ExitCode run_watch(const WatchOptions& options) {
  const RenderOptions& render_options = options.render;
  if (const auto problem = render_usage_problem(render_options)) {
    std::cerr << "pita: " << *problem << '\n';
    return ExitCode::bad_input;
  }
  std::unique_ptr<serve::FileWatcher> watcher;
  std::vector<fs::path> images;
  std::vector<fs::path> files;
  try {
    watcher = std::make_unique<serve::FileWatcher>();
    files = watched_files(render_options, images);
    watcher->watch(files);
  } catch (const std::system_error& error) {
    std::cerr << "pita: " << render_options.scene_paths.front() << ": cannot watch it (" << error.what() << ")\n";
    return ExitCode::bad_input;
  }
  int renders = 0;
  render(render_options);
  std::cerr << fmt::format(
      "pita: watching {}{} (Ctrl-C stops)\n", render_options.scene_paths.front(),
      images.empty() ? "" : fmt::format(" and {} image{}", images.size(), images.size() == 1 ? "" : "s"));
  while (options.max_renders == 0 || ++renders < options.max_renders) {
    std::set<fs::path> saved;
    while (saved.empty()) saved = watcher->wait(std::chrono::hours(1));
    render(render_options);
    try {
      // Watched anew only when the images changed: a save between the two
      // would be missed while the folders are not watched.
      std::vector<fs::path> now = watched_files(render_options, images);
      if (now != files) watcher->watch(files = std::move(now));
    } catch (const std::system_error& error) {
      std::cerr << "pita: cannot watch the scene's files any more (" << error.what() << ")\n";
      return ExitCode::failure;
    }
  }
  return ExitCode::success;
}

}  // namespace pita::cli
