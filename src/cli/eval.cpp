#include "cli/eval.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/failure.hpp"
#include "core/ease.hpp"
#include "core/methods.hpp"
#include "core/pitas/registry.hpp"
#include "core/pose_motion.hpp"
#include "io/input_file.hpp"
#include "io/output_file.hpp"
#include "motion/evaluation.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "scene/frames.hpp"
#include "scene/scene.hpp"
#include "text/list.hpp"

namespace pita::cli {

namespace {

// At most this many times may be given with --t (as many as --samples allows).
constexpr std::size_t kMaxTimes = static_cast<std::size_t>(scene::kMaxSamples);

// A problem with the input; the message is printed after "pita: ".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// Standard output as a sink: what was written cannot be taken back.
motion::TextSink stdout_sink() {
  return {
      [](std::string_view bytes) {
        if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size()) {
          throw io::OutputError(fmt::format("cannot write the frames to standard output ({})", std::strerror(errno)));
        }
      },
      false};
}

// --samples N: an integer in [kMinSamples, kMaxSamples].
int parse_samples(const std::string& text) {
  const std::string_view digits = trimmed(text);
  long long count = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), count);
  const bool integer = !digits.empty() && error == std::errc{} && end == digits.data() + digits.size();
  if (!integer || count < scene::kMinSamples || count > scene::kMaxSamples) {
    throw InputError(fmt::format("--samples: must be an integer between {} and {} (got \"{}\")", scene::kMinSamples,
                                 scene::kMaxSamples, text));
  }
  return static_cast<int>(count);
}

// --t T1,T2,...: finite reals, any order, values outside [a, c] extrapolate.
std::vector<double> parse_times(const std::string& text) {
  std::vector<double> times;
  text::for_each_item(text, [&](std::string_view listed) {
    std::string_view item = trimmed(listed);
    if (times.size() == kMaxTimes) {
      throw InputError(fmt::format("--t: at most {} times may be given", kMaxTimes));
    }
    if (item.empty()) {
      throw InputError(
          fmt::format("--t: time number {} is empty (give comma-separated numbers, "
                      "for example --t 0,0.5,1.5)",
                      times.size() + 1));
    }
    const std::string_view as_typed = item;
    if (item.front() == '+') item.remove_prefix(1);  // from_chars refuses a leading '+'
    double t = 0.0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), t);
    if (error == std::errc::result_out_of_range) {
      throw InputError(fmt::format("--t: \"{}\" is out of the range of a double", as_typed));
    }
    if (error != std::errc{} || end != item.data() + item.size()) {
      throw InputError(fmt::format("--t: \"{}\" is not a number", as_typed));
    }
    if (!std::isfinite(t)) {
      throw InputError(fmt::format("--t: \"{}\" is not a finite number", as_typed));
    }
    times.push_back(t);
  });
  return times;
}

// The eases a scene may name, from core/ease.hpp's tables.
std::string ease_names() {
  std::string names;
  for (const NamedEase& named : named_eases()) names += fmt::format("\"{}\", ", named.name);
  std::string families;
  for (const EaseFamily& family : ease_families()) {
    families += fmt::format("\n                  {}", family.syntax);
  }
  return names + "or" + families;
}

// One line of the help's table of methods: an arrow method's id, mnemonic
// and title; a pose method's id, pose count, "3D" when it moves space, title.
std::string method_line(const MethodEntry& method, Method) {
  return fmt::format("  {:<5} {:<7} {}\n", method.id, method.mnemonic, method.title);
}
std::string method_line(const MethodEntry& method, PoseMethod pose) {
  const std::string count = method.min_count == method.max_count ? std::to_string(method.min_count)
                            : method.max_count >= scene::kMaxPoses
                                ? fmt::format("{}+", method.min_count)
                                : fmt::format("{}-{}", method.min_count, method.max_count);
  return fmt::format("  {:<15} {:<4} {:<3} {}\n", method.id, count, info(pose).in_space ? "3D" : "", method.title);
}

// Every method of kind M in the registry (core/methods.hpp): the arrow
// methods (M = Method) or the pose methods (M = PoseMethod), one line each.
template <class M>
std::string methods_table() {
  std::string table;
  for (const MethodEntry& method : every_method()) {
    if (const M* of_kind = std::get_if<M>(&method.method)) table += method_line(method, *of_kind);
  }
  return table;
}

// "blend" | "neville" | ...: the chains of core/chains/chain.hpp's table.
std::string chain_list() {
  std::string list;
  for (const ChainInfo& about : all_chains()) list += fmt::format("{}\"{}\"", list.empty() ? "" : " | ", about.name);
  return list;
}

// "\"start\" (default) | \"midpoint\"": an option's values, its default
// marked (core/pitas/method_options.hpp: the default MethodOptions{} gives).
std::string choices(MethodOption option) {
  const OptionChoices about = option_choices(option);
  std::string list;
  for (const std::string_view name : about.names) {
    list += fmt::format("{}\"{}\"{}", list.empty() ? "" : " | ", name, name == about.default_name ? " (default)" : "");
  }
  return list;
}

// "La-T1, La-T2, Ne-M": the methods that read an option themselves.
std::string readers(MethodOption option) {
  std::string list;
  for (const MethodInfo& about : all_methods()) {
    if (reads_option(about.method, option, false)) list += fmt::format("{}{}", list.empty() ? "" : ", ", about.id);
  }
  return list;
}

// path_mean and magnitude_mean are listed once, on one line.
static_assert(option_choices(kPathMeanOption).default_name == option_choices(kMagnitudeMeanOption).default_name);

std::string eval_footer() {
  return R"(
Scene format (JSON; schema/scene.schema.json describes every field):
  {
    "$schema": "../schema/scene.schema.json",
    "description": "three keyframes, one with an extra turn",
    "method": "P6",
    "keyframes": [
      {"t": 0,   "p": [0, 0],   "m": 1,   "w": 0.4},
      {"t": 0.5, "p": [3, 1.5], "q": [3.5, 2]},
      {"t": 1,   "p": [6, 0],   "m": 1.2, "w": 3.5, "turns": 1}
    ],
    "samples": 9
  }
  method       a method below, by id ("P6") or mnemonic ("La-LP"), any case
  keyframes    3 or more keyframes (2 or more for SMA); knots "t" strictly increasing
    t          knot (time value)
    p          start point [x, y]
    m, w       magnitude (> 0) and winding (any real angle in radians, not reduced)
    q          end point [x, y], instead of m and w: the zero-turn arrow from p to q
    turns      integer (optional): adds 2*pi*turns to the winding
  chain        how a track of more keyframes than the method takes is built:
               )" +
         chain_list() + R"(
               (default "blend", "spiral" for SMA; docs/reference/scene-format.md "Keyframe tracks")
  points       instead of keyframes: 4 or more {"t", "p": [x, y]}; the motion is the
               point of PITA Eq. 48-50 (docs/reference/scene-format.md "Timed points"), printed as t, x, y
  samples      frames printed when neither --samples nor --t is given (default 9)
  timing       optional, how scene time runs through the motion (docs/reference/scene-format.md "Timing"):
               {"ease": E, "arc_length": "p" | "q" | "mid", "per": "motion" | "span"}
               E: )" +
         ease_names() + R"(
               frames still report the scene time t they were asked for
  options      anchor ()" +
         readers(kAnchorOption) + "): " + choices(kAnchorOption) + R"(;
               path_mean, magnitude_mean ()" +
         readers(kPathMeanOption) + R"(, and every chain's
               steady morphs): )" +
         choices(kPathMeanOption) + R"(;
               knots (every three-keyframe method): )" +
         choices(kKnotsOption) + R"(
               ("as-given": three keyframes handed to the method in the order given,
               knots distinct in any order: order-independence, Sec. 4);
               permutation ()" +
         readers(kPermutationOption) + R"(): )" + choices(kPermutationOption) + R"(;
               symmetrize ()" +
         readers(kSymmetrizeOption) + R"(): true averages with the time reverse (default )" +
         std::string(option_choices(kSymmetrizeOption).default_name) + R"();
               an option that no motion it applies to reads is refused (exit 2),
               naming the methods that read it

Methods:
)" + methods_table<Method>() +
         R"(
SMA takes two keyframes, every other method three; more are chained. Pa-Po, LS-Ca and LS-LP are the
independent combinations of Fig. 7 outside the paper's basket; He-G, La-T1, La-T2 and Ne-M are the
non-chosen candidates of appendices C and D.

Output: {"method": "P6", "frames": [{"t": 0.0, "p": [x, y], "m": 1.0, "w": 0.4, "q": [x, y]}, ...]}
with one frame per line ("chain": "blend" after "method" for a chained track), or CSV
with the header t,px,py,m,w,qx,qy. Scenes of points print {"t": .., "p": [x, y]} (CSV t,x,y).

Pose scenes (the Steady Affine Morphs paper; docs/reference/pose-scenes.md "Pose scenes"):
  {"method": "SAM",
   "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
             {"t": 1, "triangle": [[6.5, 0.5], [7.2, 2.9], [4.9, 1.6]]}]}
  matrix       [[a, b, tx], [c, d, ty]]: x -> [[a, b], [c, d]] x + [tx, ty], a d - b c != 0
  triangle     the images of "reference_triangle" (default [[0, 0], [1, 0], [0, 1]])
  method       a pose method below (any case); "subdivisions": 0-6 steps of four-point-SAM
               (default 4)
  Pose methods (id, poses, what):
)" + methods_table<PoseMethod>() +
         R"(
  Output: {"method": "SAM", "frames": [{"t": 0.0, "matrix": [[a, b, tx], [c, d, ty]]}, ...]}
  or CSV with the header t,a,b,tx,c,d,ty. When no SAM exists between two poses (their
  relative affinity has no real logarithm) pita says so and exits 2.

3D pose scenes (docs/reference/pose-scenes.md "3D pose scenes"): "dimension": 3, poses of space, the methods
marked "3D" above:
  {"dimension": 3, "method": "SAM",
   "poses": [{"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
             {"t": 1, "tetrahedron": [[2, 0, 0], [2, 1, 0], [1, 0, 0], [2, 0, 1]]}]}
  matrix       [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]], invertible
  tetrahedron  the images of "reference_tetrahedron" (default the origin and the unit
               points of the axes)
  Output: {"method": "SAM", "frames": [{"t": 0.0, "matrix": [[a, b, c, tx], ...]}, ...]}
  or CSV with the header t,a,b,c,tx,d,e,f,ty,g,h,i,tz. pita render draws them (docs/reference/pose-scenes.md).

Examples:
  pita eval scenes/fig01-eight-pitas.json
  pita eval scenes/fig01-eight-pitas.json --method P8 --samples 5 --format csv
  pita eval scenes/fig28-prediction.json --t 0,0.5,1,1.5
  pita eval scenes/fig01-eight-pitas.json --samples 1000000 --format csv -o frames.csv
  pita eval scenes/sam-fig01-regular-patterns.json --method linear --format csv

Exit codes: 0 success, 2 bad input or usage (the message on stderr names the file,
the JSON Pointer of the bad value and what is wrong; nothing is printed on stdout;
also out of memory), 3 the frames could not be written to standard output (a closed
pipe included) or to -o FILE, 4 an internal error (a bug in pita).

The frames are streamed: a million of them take no more memory than a few. Every frame
is computed and checked once before the first byte goes to standard output (a frame
that is not finite leaves it empty); with -o FILE they go into a temporary beside FILE,
renamed into place only when all were written.
)";
}

}  // namespace

std::shared_ptr<EvalOptions> setup_eval(CLI::App& app) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* eval = app.add_subcommand("eval", "Evaluate the motion through a scene's keyframes and print its frames");
  eval->footer(eval_footer());

  // Not ->required(): --batch replaces it (run_eval says when neither is given).
  eval->add_option("SCENE", options->scene_path, "Scene file (JSON), for example scenes/fig01-eight-pitas.json");
  eval->add_option_function<std::string>(
          "--method", [options](const std::string& name) { options->method = name; },
          "Use this method instead of the scene's (the keyframe count must fit it)")
      ->type_name("M");
  CLI::Option* samples = eval->add_option_function<std::string>(
                                 "--samples", [options](const std::string& count) { options->samples = count; },
                                 "Print N frames at evenly spaced times from the first knot to the last "
                                 "(2 <= N <= 1000000; default: the scene's \"samples\", else 9)")
                             ->type_name("N");
  CLI::Option* times = eval->add_option_function<std::string>(
                               "--t", [options](const std::string& list) { options->times = list; },
                               "Print the frames at these times: comma-separated finite numbers, any order; "
                               "times outside the knots extrapolate")
                           ->type_name("T1,T2,...");
  samples->excludes(times);
  eval->add_option_function<int>(
          "--panel", [options](const int& index) { options->panel = index; },
          "Evaluate the motion of this panel of the scene (0 = the first entry of \"panels\") instead of the "
          "scene's own")
      ->type_name("N");
  eval->add_option_function<std::string>(
          "--format",
          [options](const std::string& format) {
            options->format = format;
            options->format_given = true;
          },
          "Output format (default json, or the extension of -o: frames.csv)")
      ->check(CLI::IsMember({"json", "csv"}))
      ->type_name("FORMAT");
  eval->add_option_function<std::string>(
          "-o,--output", [options](const std::string& path) { options->output = path; },
          "Write the frames into FILE instead of standard output: atomically, through a temporary beside it "
          "renamed into place, so FILE is either complete or untouched")
      ->type_name("FILE");
  eval->add_option_function<std::string>(
          "--batch", [options](const std::string& path) { options->batch = path; },
          "Many evaluations in one process: each line of FILE (- for standard input) is the arguments of one "
          "`pita eval` as a JSON array of strings; each line printed is its {\"exit\", \"stdout\", \"stderr\"} "
          "(docs/reference/eval.md \"Many evaluations in one process\")")
      ->type_name("FILE");
  return options;
}

namespace {

// evaluate(), handing the frames to `sink` as they are printed.
EvalOutcome evaluate_into(const EvalOptions& options, const motion::TextSink& sink) {
  EvalOutcome outcome;
  try {
    // An unknown name is refused before the scene is read; a known one is
    // looked up among the methods of the scene's kind (scene::with_method).
    if (options.method && find_method_entry(*options.method) == nullptr) {
      throw InputError(fmt::format("--method: {}", unknown_method_reason(*options.method)));
    }
    std::optional<std::vector<double>> times;
    if (options.times) times = parse_times(*options.times);
    std::optional<int> samples;
    if (options.samples) samples = parse_samples(*options.samples);

    scene::Scene scene = scene::load_scene(options.scene_path);
    if (options.method) scene = scene::with_method(std::move(scene), std::string_view(*options.method));

    // the whole output is built before anything is printed
    if (!scene::has_motion_keys(scene.keys)) {
      // A figure whose layers need no motion (sam-fig06-existence-3d): a
      // well-formed, empty result and a note on stderr, exit 0, so that a loop
      // over every scene (scripts/run.sh) goes through (docs/paper-notes.md N68).
      if (options.panel) {
        throw InputError(
            fmt::format("--panel: {}: /poses: the scene has no poses, so no motion to evaluate", scene.path));
      }
      sink.write(motion::no_frames_text(
          scene, options.format == "csv" ? motion::FramesFormat::csv : motion::FramesFormat::json));
      outcome.err = fmt::format("pita: {}: /poses: the scene has no poses, so no motion: no frames\n", scene.path);
      return outcome;
    }
    // Every panel's motion first (a scene is judged alike by every command),
    // then the flags, then the panel's range.
    std::optional<motion::Evaluation> evaluation;
    try {
      evaluation.emplace(scene, options.method ? std::nullopt : options.panel);
    } catch (const std::out_of_range& error) {
      throw InputError(fmt::format("--panel: {}", error.what()));
    }
    if (options.panel && options.method) {
      throw InputError(
          "--panel and --method: a panel evaluates with its own method; give --method without "
          "--panel for the scene's motion, or change the panel's \"method\"");
    }
    const scene::Panel& panel = evaluation->panel();
    const motion::SceneMotion& motion = evaluation->motion();
    const motion::FrameTimes at =
        times ? motion::FrameTimes(*times)
              : motion::FrameTimes(motion, samples.value_or(scene.samples.value_or(scene::kDefaultSamples)));
    outcome.work = motion::check_eval_work(scene, panel, motion, at.size(), "ask for fewer frames (--samples, --t)");
    motion::write_frames(panel, motion, at,
                         options.format == "csv" ? motion::FramesFormat::csv : motion::FramesFormat::json, sink);
    return outcome;
  } catch (const InputError& error) {
    return EvalOutcome{ExitCode::bad_input, {}, fmt::format("pita: {}\n", error.what()), 0.0};
  } catch (...) {
    const Failure failure = current_failure(options.scene_path);
    return EvalOutcome{failure.code, {}, fmt::format("pita: {}\n", failure.message), 0.0};
  }
}

}  // namespace

EvalOutcome evaluate(const EvalOptions& options) {
  std::string text;
  EvalOutcome outcome = evaluate_into(options, motion::TextSink{[&](std::string_view bytes) { text += bytes; }});
  if (outcome.code == ExitCode::success) outcome.out = std::move(text);
  return outcome;
}

namespace {

namespace fs = std::filesystem;

// -o FILE.csv or FILE.json: the frames in that format (--format, if given,
// must agree); another extension is a mistake (a figure is pita render's),
// refused before anything is read.
std::optional<std::string> output_format_error(EvalOptions& options) {
  if (!options.output) return std::nullopt;
  const fs::path out(*options.output);
  if (!out.has_extension() || out.extension() == ".") return std::nullopt;
  const std::string ext = out.extension().string().substr(1);
  if (ext != "csv" && ext != "json") {
    return fmt::format(
        "-o {}: pita eval writes frames as .csv or .json files (\".{}\" is neither; pita render draws figures), or "
        "a file without an extension in the --format given",
        *options.output, ext);
  }
  if (options.format_given && options.format != ext) {
    return fmt::format("--format {} contradicts the extension of -o {}", options.format, *options.output);
  }
  options.format = ext;
  return std::nullopt;
}

}  // namespace

ExitCode run_eval(const EvalOptions& given) {
  EvalOptions options = given;
  if (const std::optional<std::string> error = output_format_error(options)) {
    std::cerr << "pita: " << *error << "\nRun 'pita eval --help' for usage.\n";
    return ExitCode::bad_input;
  }
  // The frames never replace the scene they are read from.
  if (options.output && !options.scene_path.empty() && io::same_file(*options.output, options.scene_path)) {
    std::cerr << fmt::format(
        "pita: -o {}: the output is the scene file {}, which it would replace: write the frames "
        "elsewhere\n",
        *options.output, options.scene_path);
    return ExitCode::bad_input;
  }
  if (options.batch) {
    // Checked here rather than with CLI11's excludes(), which would print
    // "Excludes: --batch" beside every option of the help.
    if (!options.scene_path.empty() || options.method || options.samples || options.times || options.panel ||
        options.format_given || options.output) {
      std::cerr << "pita: --batch excludes SCENE, --method, --samples, --t, --panel, --format and -o: each "
                   "request line holds its own, and the answers go to standard output\nRun 'pita eval --help' "
                   "for usage.\n";
      return ExitCode::bad_input;
    }
    return run_eval_batch(*options.batch);
  }
  if (options.scene_path.empty()) {
    std::cerr << "pita: SCENE is required\nGive a scene file, or --batch FILE for many evaluations in one "
                 "process. Run 'pita eval --help' for usage.\n";
    return ExitCode::bad_input;
  }
  if (!options.output) {
    EvalOutcome outcome = evaluate_into(options, stdout_sink());
    if (outcome.code == ExitCode::success && std::fflush(stdout) != 0) {
      outcome = {ExitCode::failure,
                 {},
                 fmt::format("pita: cannot write the frames to standard output ({})\n", std::strerror(errno))};
    }
    std::cerr << outcome.err;
    return outcome.code;
  }
  // The file is opened at the first bytes, so that a bad scene is reported
  // (exit 2) before an unwritable output (exit 3), and dropped unless every
  // frame was written.
  std::optional<io::StreamingOutput> file;
  const motion::TextSink file_sink{[&](std::string_view bytes) {
                                     if (!file) file.emplace(*options.output);
                                     file->write(bytes);
                                   },
                                   true};
  EvalOutcome outcome = evaluate_into(options, file_sink);
  if (outcome.code == ExitCode::success) {
    try {
      if (!file) file.emplace(*options.output);
      file->commit();
    } catch (const io::OutputError& error) {
      outcome = {ExitCode::failure, {}, fmt::format("pita: {}\n", error.what())};
    }
  }
  std::cerr << outcome.err;
  return outcome.code;
}

}  // namespace pita::cli
