#include "cli/animate.hpp"

#include <cmath>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "animate/output.hpp"
#include "animate/timeline.hpp"
#include "cli/environment.hpp"
#include "cli/failure.hpp"
#include "cli/render_plan.hpp"
#include "render/budget.hpp"
#include "render/figure.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::cli {

namespace {

constexpr const char* kFooter = R"(
OUT decides what is written:
  OUT.svg             one animated SVG (SMIL, no script) that plays and loops in a browser
  OUT.mp4, OUT.webm   a video: raw frames piped into ffmpeg (Debian package ffmpeg)
  OUT or OUT/         a directory: frame-0001.png ... (--format svg: .svg) and frames.json,
                      which gives each frame's time t and D(t) (A(t) for poses)
Any other extension is refused (exit 2).

The scene's "animation" {"duration": 4, "fps": 30, "frames": N, "loop": true,
"what": "motion" | "pattern", "trail": k, "overlay": [tau, ...]} sets the defaults;
--fps, --duration and --frames override it (N = round(duration x fps) unless
frames are given; --frames with --duration sets fps = frames / duration).
"motion": the frame D(t) (the "pattern" layers) and the shapes it carries (the
"shapes" layers) run over the knots [t_0, t_n], the last k frames fading behind;
other layers stay. "pattern": keyframes {"t", "from", "to"} move by steady morphs
as tau runs over [0, 1], and the whole figure follows (PITA Sec. 7.4).
Frame k (0-based) of N is at t_0 + (t_n - t_0) k / (N - 1), or k / N when the
animation loops; the scene's "timing" shapes how the motion runs through them.
Frame k equals `pita render SCENE --at t_k` pixel for pixel (give render the same
--fps, --duration or --frames: they space the frames of a "trail").

Frames are drawn in parallel (PITA_THREADS, default every core) and streamed:
memory does not grow with the number of frames. Everything is written to a
temporary beside OUT and renamed into place (an older frame directory is
swapped atomically); SIGINT, SIGTERM and SIGHUP stop the work, remove the
temporaries and exit with 128 + signal. A progress bar shows on a terminal.

Examples:
  pita animate scenes/fig23-image-motion.json -o fig23.svg
  pita animate scenes/fig23-image-motion.json -o frames/ --frames 24
  pita animate scenes/fig27-animated-pattern.json -o fig27.mp4 --fps 24

Exit codes: 0 success, 2 bad input or usage (also ffmpeg missing), 3 an output
could not be written, 4 an internal error, 128 + N interrupted by signal N.
)";

}  // namespace

std::shared_ptr<AnimateOptions> setup_animate(CLI::App& app) {
  auto options = std::make_shared<AnimateOptions>();
  CLI::App* animate = app.add_subcommand("animate", "Play a scene: animated SVG, video (ffmpeg) or frames");
  animate->footer(kFooter);
  animate->add_option("SCENE", options->scene_path, "Scene file (JSON)")->required();
  animate->add_option("-o,--output", options->output, "OUT.svg, OUT.mp4, OUT.webm or a directory")
      ->required()
      ->type_name("OUT");
  animate
      ->add_option_function<double>(
          "--fps", [options](double v) { options->fps = v; },
          fmt::format("Frames per second, (0, {:g}]", scene::kMaxFps))
      ->type_name("F");
  animate
      ->add_option_function<double>(
          "--duration", [options](double v) { options->duration = v; }, "Seconds, > 0")
      ->type_name("S");
  animate
      ->add_option_function<int>(
          "--frames", [options](int v) { options->frames = v; },
          fmt::format("Number of frames, {} to {}; alone it keeps the frames per second, so the animation plays "
                      "N / fps seconds (give --duration too to keep its length)",
                      scene::kMinAnimationFrames, scene::kMaxAnimationFrames))
      ->type_name("N");
  animate
      ->add_option("--scale", options->scale,
                   fmt::format("Pixels per canvas pixel of PNG frames and video ({} to {}; default 1)",
                               render::kMinScale, render::kMaxScale))
      ->type_name("S");
  animate
      ->add_option_function<std::string>(
          "--format", [options](const std::string& v) { options->format = v; },
          "Frames of a directory: png (default) or svg")
      ->type_name("FMT");
  animate->add_flag("-q,--quiet", options->quiet, "No progress bar and no \"wrote\" line: errors only");
  animate->add_flag("--allow-absolute-paths", options->allow_absolute_paths, "Allow images given by absolute paths");
  animate->add_option("--budget", options->budget, "Allow F times the default work budget of a frame")
      ->check(CLI::Range(1e-3, render::kMaxBudgetFactor))
      ->type_name("F");
  return options;
}

ExitCode run_animate(const AnimateOptions& options) {
  animate::Request request;
  try {
    request.kind = animate::output_kind(options.output);
    if (options.format) {
      const auto format = render::format_from_name(*options.format);
      if (request.kind != animate::AnimationOutput::directory) {
        throw animate::AnimationError(
            fmt::format("--format {}: only a directory of frames takes a format; -o {} "
                        "is a single file",
                        *options.format, options.output));
      }
      if (!format || *format == render::Format::pdf) {
        throw animate::AnimationError(
            fmt::format("--format: \"{}\" is not a frame format (png or svg)", *options.format));
      }
      request.frame_format = *format;
    }
    if (!std::isfinite(options.budget)) {
      throw animate::AnimationError(fmt::format("--budget: must be a number (got {})", options.budget));
    }
    if (!(options.scale >= render::kMinScale && options.scale <= render::kMaxScale)) {
      throw animate::AnimationError(fmt::format("--scale: must be between {} and {} (got {})", render::kMinScale,
                                                render::kMaxScale, options.scale));
    }
  } catch (const animate::AnimationError& error) {
    std::cerr << "pita: " << error.what() << '\n';
    return ExitCode::bad_input;
  }
  request.out = options.output;
  request.scale = options.scale;
  request.budget = options.budget;
  request.progress = progress_allowed(options.quiet);
  request.threads = threads_from_environment();
  request.ffmpeg = ffmpeg_from_environment();
  try {
    const scene::Scene scene = scene::load_scene(options.scene_path, {options.allow_absolute_paths, std::nullopt});
    refuse_an_input(scene, options.output);  // an animated SVG or a video never replaces an input
    const animate::Timeline timeline = animate::make_timeline(scene, {options.fps, options.duration, options.frames});
    for (const auto& path : animate::write_animation(scene, timeline, request)) {
      if (options.quiet) continue;
      std::cout << fmt::format("wrote {} ({} frames at {:g} fps: {:g} s)\n", path.string(), timeline.frames,
                               timeline.fps, timeline.seconds());
    }
    return ExitCode::success;
  } catch (...) {
    const Failure failure = current_failure(options.scene_path);
    std::cerr << "pita: " << failure.message << '\n';
    return failure.code;
  }
}

}  // namespace pita::cli
