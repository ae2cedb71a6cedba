#include "cli/render.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "analysis/claims.hpp"
#include "animate/frame.hpp"
#include "animate/timeline.hpp"
#include "cli/failure.hpp"
#include "cli/render_plan.hpp"
#include "cli/scene_jobs.hpp"
#include "cli/usage_error.hpp"
#include "core/methods.hpp"
#include "io/output_file.hpp"
#include "motion/stage.hpp"
#include "render/budget.hpp"
#include "render/figure.hpp"
#include "render/panel_drawing.hpp"
#include "scene/figure_reader.hpp"
#include "scene/image_file.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"
#include "text/list.hpp"

namespace pita::cli {

namespace {

namespace fs = std::filesystem;

// "pattern" | "keyframes" | ...: the layer kinds of the reader's one table,
// wrapped after `width` characters with `indent` spaces.
std::string layer_kind_list(const std::vector<scene::detail::LayerKindInfo>& kinds) {
  std::string text, line;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    const std::string item = fmt::format("\"{}\"{}", kinds[i].type, i + 1 < kinds.size() ? " | " : "");
    if (line.size() + item.size() > 70) {
      text += line.substr(0, line.find_last_not_of(' ') + 1) + "\n           ";
      line.clear();
    }
    line += item;
  }
  return text + line;
}

std::string render_footer() {
  std::string text = R"(
OUT is a file when it ends in .svg, .png or .pdf (one scene; the format is its
extension), otherwise a directory (created if needed) that receives
OUT/<scene name>.<format> for each --format (default svg). Any other extension
(-o four.jpg) is refused with exit 2, unless OUT is an existing directory.

<scene name> is the scene file's name without its directory and extension:
files never land outside OUT (a symlink OUT is followed). Two scenes with the
same name (a/x.json and b/x.json), or one scene given twice, are refused with
exit 2 before anything is written.

Each file is written to a temporary file and renamed into place, a scene's
formats all or none: a failed scene leaves no file behind (its older files
stay as they were), and the other scenes are still rendered. SIGINT, SIGTERM
and SIGHUP remove the unfinished temporary files and exit with 128 + signal.
Output is deterministic: the same scene gives the same bytes.

A figure's work is estimated before anything is drawn (panels x layers x
frames, trajectory and banner points, existence cells, PNG pixels) and refused
above a budget, naming the field that dominates; --budget F allows F times it.

Scene fields for figures (see docs/reference/render.md "Figures" and schema/scene.schema.json):
  title, canvas {width, height, background, view, margin, y_axis, columns, font},
  layers [{"type": @ARROW_LAYERS@, ...}],
  panels ["P1", {"method": "P2", "keyframes": [...], "chain": "blend", "title": "..."}, ...]
  keyframes: 3 or more (SMA: 2 or more), chained by "chain" (docs/reference/scene-format.md "Keyframe tracks");
  points [{"t": 0, "p": [x, y]}, ...] instead of keyframes: 4 or more timed points,
  drawn by "point-trajectory" layers
Pose scenes (SAM paper, docs/reference/pose-scenes.md "Pose scenes") draw shapes carried by the poses:
  shapes [{"outline": "F"} | {"triangle": "reference"} | {"polygon": [[x, y], ...]}],
  layers [{"type": @POSE_LAYERS@, ...}],
  panels ["linear", {"method": "biarc-SAM", "poses": [...], "title": "..."}, ...]

--at T draws one frame of the scene's animation (docs/reference/animate.md "Animation"): at scene
time T ("what": "motion": the pattern layers draw D(T) and its trail, the shapes
layers the shapes it carries), or at tau = T for keyframes that move ("what":
"pattern"); in the view every frame of `pita animate` shares, so that frame k
of `pita animate` equals `pita render --at t_k` (given the same --fps, --duration
and --frames, which space the frames of a "trail").

Arrow scenes may carry shapes and PNG images with the frames (PITA Sec. 7.1):
  shapes [{"polygon": ...} | {"outline": "F"} | {"image": "x.png", "box": [[x0, y0], [x1, y1]]}],
  handle {"p": [x, y], "q": [x, y]} (default: the first keyframe), drawn by "shapes" layers;
  image paths are relative to the scene's folder (--allow-absolute-paths for absolute ones).

Examples:
  pita render scenes/fig01-eight-pitas.json -o fig01.png --scale 2
  pita render scenes/fig23-image-motion.json --at 0.5 -o frame.png
  pita render scenes/*.json -o out --format svg,png
  pita render scenes/fig25-strokes.json -o out --format pdf
  pita render scenes/sam-fig07-no-sam-biarc.json -o fig7.png

Exit codes: 0 success, 2 bad input or usage (also beyond the budget, out of memory),
3 an output could not be written, 4 an internal error (a bug), 128 + N interrupted by
signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP; unfinished temporary files removed).
)";
  // The layer kinds come from the reader's one table of them.
  const auto substitute = [&text](const std::string& key, const std::string& value) {
    text.replace(text.find(key), key.size(), value);
  };
  substitute("@ARROW_LAYERS@", layer_kind_list(scene::detail::arrow_layer_kinds()));
  substitute("@POSE_LAYERS@", layer_kind_list(scene::detail::pose_layer_kinds()));
  return text;
}

}  // namespace

std::shared_ptr<RenderOptions> setup_render(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* render = app.add_subcommand("render", "Draw the figures of scenes as SVG, PNG or PDF");
  render->footer(render_footer());
  // Required unless --list: checked in run_render, with CLI11's words.
  render->add_option("SCENE", options->scene_paths, "Scene files (JSON)");
  render->add_option("-o,--output", options->output, "Output file (.svg/.png/.pdf) or directory")->type_name("OUT");
  render
      ->add_option_function<std::string>(
          "--method", [options](const std::string& name) { options->method = name; },
          "Draw the scene as if its \"method\" were M: its own motion and every panel without a method of its "
          "own (a title's {/method} shows M)")
      ->type_name("M");
  render->add_flag("--list", options->list,
                   "Print every scene (of the SCENE files and folders given, else of ./scenes) with its title and "
                   "description, and render nothing");
  render
      ->add_option_function<std::string>(
          "--format", [options](const std::string& list) { options->formats = list; },
          "Formats to write into the OUT directory, comma-separated: svg,png,pdf (default svg)")
      ->type_name("LIST");
  CLI::Option* scale =
      render
          ->add_option_function<double>(
              "--scale", [options](double s) { options->scale = s; },
              fmt::format("PNG pixels per canvas pixel ({} to {}; default 1)", render::kMinScale, render::kMaxScale))
          ->type_name("S");
  CLI::Option* dpi = render
                         ->add_option_function<double>(
                             "--dpi", [options](double d) { options->dpi = d; }, "PNG resolution: scale = DPI / 96")
                         ->type_name("DPI");
  scale->excludes(dpi);
  render
      ->add_option(
          "--budget", options->budget,
          fmt::format("Allow F times the default work budget of a figure ({:.0f} million "
                      "drawn points, {:.0f} million PNG pixels; about 5 s and 400 MB "
                      "each); at most {:g}",
                      render::kDefaultBudgetUnits / 1e6, render::kDefaultBudgetPixels / 1e6, render::kMaxBudgetFactor))
      ->check(CLI::Range(1e-3, render::kMaxBudgetFactor))
      ->type_name("F");
  render
      ->add_option_function<double>(
          "--at", [options](double t) { options->at = t; },
          "Draw the scene's animation at time T (a scene time; tau in [0, 1] for an animated "
          "pattern): the frame `pita animate` draws at T")
      ->type_name("T");
  CLI::Option* fps = render
                         ->add_option_function<double>(
                             "--fps", [options](double v) { options->fps = v; },
                             "With --at: the animation's frames per second, as for `pita animate`")
                         ->type_name("F");
  CLI::Option* duration = render
                              ->add_option_function<double>(
                                  "--duration", [options](double v) { options->duration = v; },
                                  "With --at: the animation's duration in seconds")
                              ->type_name("S");
  CLI::Option* frames =
      render
          ->add_option_function<int>(
              "--frames", [options](int v) { options->frames = v; }, "With --at: the animation's number of frames")
          ->type_name("N");
  for (CLI::Option* clock : {fps, duration, frames}) clock->needs("--at");
  render->add_flag("--allow-absolute-paths", options->allow_absolute_paths, "Allow images given by absolute paths");
  add_scene_jobs_option(*render, options->jobs);
  return options;
}

namespace {

// --list: name, title and description of each scene, sorted by name.
ExitCode list_scenes(const RenderOptions& options) {
  std::vector<fs::path> files;
  const std::vector<std::string> given =
      options.scene_paths.empty() ? std::vector<std::string>{"scenes"} : options.scene_paths;
  for (const std::string& path : given) {
    std::error_code error;
    if (fs::is_directory(path, error)) {
      std::vector<fs::path> found;
      for (const fs::directory_entry& entry : fs::directory_iterator(path, error)) {
        if (entry.path().extension() == ".json") found.push_back(entry.path());
      }
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.emplace_back(path);
    }
  }
  if (files.empty()) {
    std::cerr << "pita: --list: no scene files (*.json) in " << fmt::format("{}", fmt::join(given, ", ")) << '\n';
    return ExitCode::bad_input;
  }
  ExitCode result = ExitCode::success;
  std::string text;
  for (const fs::path& file : files) {
    try {
      const scene::Scene scene = scene::load_scene(file, {options.allow_absolute_paths, std::nullopt});
      text += fmt::format("{}\n", file.stem().string());
      if (!scene.title.empty()) text += fmt::format("    {}\n", scene.title);
      if (!scene.description.empty()) text += fmt::format("    {}\n", scene.description);
    } catch (...) {
      const Failure failure = current_failure(file.string());
      std::cerr << "pita: " << failure.message << '\n';
      result = worse(result, failure.code);
    }
  }
  std::cout << text;
  return result;
}

// One scene's figure (or its frame at --at) in every format of the plan, and
// what it warns about, rendered on a worker thread and written by
// write_scene on the calling thread.
struct RenderedScene {
  std::string warnings;  // lines for stderr
  std::vector<std::pair<fs::path, std::string>> files;
  std::optional<Failure> failure;
};

// Every format is rendered before any is written, so a bad scene writes
// nothing.
RenderedScene render_scene(const RenderOptions& options, const RenderPlan& plan, const std::string& path) {
  RenderedScene rendered;
  const scene::Scene scene = scene::load_scene(path, {options.allow_absolute_paths, options.method});
  render::Figure figure;
  if (options.at) {
    // One frame of the animation, in the view all its frames share.
    const animate::Timeline timeline = animate::make_timeline(scene, {options.fps, options.duration, options.frames});
    render::check_budget(scene, render::estimate_cost(scene), options.budget);
    render::check_images(scene);
    figure = animate::frame_figure(scene, timeline, *options.at, animate::animation_layout(scene, timeline));
  } else {
    const motion::Stage stage(scene);
    figure = render::build_figure(stage, options.budget);
    // The caption's claims, measured on the motions drawn: a warning here,
    // a failure in `pita check` (docs/reference/check.md "Claims").
    for (const analysis::ClaimOutcome& claim : analysis::check_claims(stage)) {
      if (claim.held) continue;
      rendered.warnings +=
          "pita: warning: " +
          scene::located(scene.path, claim.pointer,
                         fmt::format("the claim \"{}\" does not hold: {}", claim.says, claim.measured)) +
          '\n';
    }
  }
  for (const Target& target : targets_for(options, path, plan.formats, plan.single_file)) {
    refuse_an_input(scene, target.path);
    rendered.files.emplace_back(target.path,
                                render::render_figure(scene, figure, target.format, plan.scale, options.budget));
  }
  return rendered;
}

// The files of a scene are written all or none (io/output_file.hpp).
void write_scene(const RenderedScene& rendered) {
  io::write_files_atomically(rendered.files);
  for (const auto& [file, bytes] : rendered.files) std::cout << "wrote " << file.string() << '\n';
  // Flushed, so that an interrupted run still lists what it wrote.
  std::cout.flush();
}

}  // namespace

std::optional<std::string> render_usage_problem(const RenderOptions& options) {
  try {
    plan_render(options);
    return std::nullopt;
  } catch (const UsageError& error) {
    return std::string(error.what());
  }
}

std::vector<std::string> render_and_write(const RenderOptions& options, std::string& warnings) {
  const RenderPlan plan = plan_render(options);
  if (!plan.single_file) {
    std::error_code error;
    fs::create_directories(options.output, error);  // when it fails, writing says why
  }
  const RenderedScene rendered = render_scene(options, plan, options.scene_paths.at(0));
  warnings += rendered.warnings;
  io::write_files_atomically(rendered.files);
  std::vector<std::string> written;
  for (const auto& [file, bytes] : rendered.files) written.push_back(file.string());
  return written;
}

ExitCode run_render(const RenderOptions& options) {
  if (options.list) return list_scenes(options);
  if (options.scene_paths.empty()) {
    std::cerr << "pita: SCENE is required\nRun 'pita render --help' for usage.\n";
    return ExitCode::bad_input;
  }
  if (options.output.empty()) {
    std::cerr << "pita: --output is required\nRun 'pita render --help' for usage.\n";
    return ExitCode::bad_input;
  }
  RenderPlan plan;
  try {
    plan = plan_render(options);
  } catch (const UsageError& error) {
    std::cerr << "pita: " << error.what() << '\n';
    return ExitCode::bad_input;
  }
  if (!plan.single_file) {
    std::error_code error;
    fs::create_directories(options.output, error);
    if (error || !fs::is_directory(options.output)) {
      std::cerr << "pita: -o " << options.output << ": cannot create the output directory ("
                << (error ? error.message() : "a file of that name exists") << ")\n";
      return ExitCode::failure;
    }
  }
  ExitCode result = ExitCode::success;
  const auto fail = [&](const Failure& failure) {
    std::cerr << "pita: " << failure.message << '\n';
    result = worse(result, failure.code);
  };
  for_each_scene(
      options.scene_paths.size(), scene_jobs(options.jobs),
      [&](std::size_t i) {
        try {
          return render_scene(options, plan, options.scene_paths[i]);
        } catch (...) {
          return RenderedScene{{}, {}, current_failure(options.scene_paths[i])};
        }
      },
      [&](std::size_t i, RenderedScene rendered) {
        std::cerr << rendered.warnings;
        if (rendered.failure) return fail(*rendered.failure);
        try {
          write_scene(rendered);
        } catch (...) {
          fail(current_failure(options.scene_paths[i]));
        }
      });
  return result;
}

}  // namespace pita::cli
