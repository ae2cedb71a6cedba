// pita.load_scene(path_or_dict) and pita.Scene: a scene file (or a dict in
// its format) read and checked once, then evaluated, drawn, animated,
// measured and checked against goldens by the layers the commands use:
// Scene.eval is `pita eval`, render `pita render`, animate `pita animate`,
// measure `pita measure --format json`, check `pita check`.
#include "scene/scene.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include "analysis/measure.hpp"
#include "analysis/measure_report.hpp"
#include "animate/frame.hpp"
#include "animate/frame_runner.hpp"
#include "animate/output.hpp"
#include "animate/svg_animation.hpp"
#include "animate/timeline.hpp"
#include "animate/video.hpp"
#include "core/methods.hpp"
#include "core/overloaded.hpp"
#include "golden/check.hpp"
#include "io/input_file.hpp"
#include "motion/evaluation.hpp"
#include "motion/sampler.hpp"
#include "python/bindings.hpp"
#include "python/chunks.hpp"
#include "python/held_scene.hpp"
#include "render/figure.hpp"
#include "scene/limits.hpp"

namespace pita::python {

namespace {

// Shared from this: a figure drawn on a thread of its own keeps it alive.
struct HeldScene : std::enable_shared_from_this<HeldScene> {
  scene::Scene scene;
  std::optional<std::filesystem::path> file;  // the file it was read from; none for a dict
};

// The scene with another method, as `pita eval --method` makes it.
scene::Scene with_method(const scene::Scene& scene, const std::string& name) {
  if (find_method_entry(name) == nullptr) {
    throw py::value_error(fmt::format("method: {}", unknown_method_reason(name)));
  }
  return scene::with_method(scene, std::string_view(name));
}

// No frames, shaped as the kind's (a scene without poses: sam-fig06-existence-3d).
py::object no_frames(const scene::Scene& scene) {
  const bool space = std::holds_alternative<scene::SpacePoseKeys>(scene.keys);
  return py::array_t<double>(space ? std::vector<py::ssize_t>{0, 3, 4} : std::vector<py::ssize_t>{0, 2, 3});
}

// What Scene.eval computes from, owned: the text of frames is made on a
// thread that may outlive the call (run_interruptible).
struct EvalWork {
  scene::Scene scene;
  std::optional<motion::Evaluation> evaluation;  // refers to `scene`: this object does not move
  std::vector<double> times;
};

py::object eval(const HeldScene& held, const py::object& t, std::optional<int> samples, std::optional<int> panel,
                std::optional<std::string> method, std::optional<std::string> format) {
  if (format && *format != "json" && *format != "csv") {
    throw py::value_error(
        fmt::format("format: \"{}\" is not a format (use \"json\" or \"csv\", or None for arrays)", *format));
  }
  if (samples && (*samples < scene::kMinSamples || *samples > scene::kMaxSamples)) {
    throw py::value_error(
        fmt::format("samples: must be between {} and {} (got {})", scene::kMinSamples, scene::kMaxSamples, *samples));
  }
  if (samples && !t.is_none()) throw py::value_error("samples and t: give one (t: the times; samples: how many)");
  if (panel && method) {
    throw py::value_error(
        "panel and method: a panel evaluates with its own method; give method without panel "
        "for the scene's motion");
  }
  const auto work = std::make_shared<EvalWork>();
  work->scene = method ? with_method(held.scene, *method) : held.scene;
  const scene::Scene& scene = work->scene;
  if (!scene::has_motion_keys(scene.keys)) {
    if (panel) throw py::value_error(fmt::format("panel: {}: the scene has no poses, so no motion", scene.path));
    if (!format) return no_frames(scene);
  }
  std::optional<motion::Evaluation>& evaluation = work->evaluation;
  if (scene::has_motion_keys(scene.keys)) {
    try {
      evaluation.emplace(scene, panel);
    } catch (const std::out_of_range& error) {
      throw py::value_error(fmt::format("panel: {}", error.what()));
    }
  }
  constexpr const char* kAdvice = "ask for fewer frames (samples=, t=)";
  Times times;
  if (!t.is_none()) {
    // The work from the count of the times, before they are copied.
    times = read_times(t, "t", [&](std::size_t count) {
      if (evaluation) motion::check_eval_work(scene, evaluation->panel(), evaluation->motion(), count, kAdvice);
    });
  } else if (evaluation) {
    times.values =
        motion::uniform_times(evaluation->motion(), samples.value_or(scene.samples.value_or(scene::kDefaultSamples)));
    times.shape = {static_cast<py::ssize_t>(times.values.size())};
  }
  if (format) {
    const motion::FramesFormat frames_format =
        *format == "csv" ? motion::FramesFormat::csv : motion::FramesFormat::json;
    if (!evaluation) return py::str(motion::no_frames_text(scene, frames_format));  // as `pita eval` prints it
    motion::check_eval_work(scene, evaluation->panel(), evaluation->motion(), times.values.size(), kAdvice);
    work->times = std::move(times.values);
    // One text, not cut into chunks: made on a thread of its own while this
    // one sees Ctrl-C.
    return py::str(run_interruptible([work, frames_format] {
      return motion::frames_text(work->evaluation->panel(), work->evaluation->motion(), work->times, frames_format);
    }));
  }
  motion::check_eval_work(scene, evaluation->panel(), evaluation->motion(), times.values.size(), kAdvice);
  return sample(evaluation->motion(), times);
}

render::Format render_format(const std::string& name) {
  const auto format = render::format_from_name(name);
  if (!format)
    throw py::value_error(fmt::format("format: \"{}\" is not a format (use \"svg\", \"png\" or \"pdf\")", name));
  return *format;
}

py::bytes render_bytes(const HeldScene& source, const std::string& format_name, double scale, std::optional<double> at,
                       double budget) {
  const std::shared_ptr<const HeldScene> held = source.shared_from_this();
  const render::Format format = render_format(format_name);
  if (!(scale >= render::kMinScale && scale <= render::kMaxScale)) {
    throw py::value_error(
        fmt::format("scale: must be between {} and {} (got {})", render::kMinScale, render::kMaxScale, scale));
  }
  if (!(budget > 0.0 && budget <= 1000.0)) throw py::value_error("budget: must be in (0, 1000]");
  // One figure, drawn on a thread of its own while this one sees Ctrl-C
  // (the scene is kept alive by `held` until the drawing ends).
  const std::string bytes = run_interruptible([held, format, scale, at, budget] {
    render::Figure figure;
    if (at) {
      const animate::Timeline timeline = animate::make_timeline(held->scene);
      figure = animate::frame_figure(held->scene, timeline, *at, animate::animation_layout(held->scene, timeline));
    } else {
      figure = render::build_figure(held->scene, budget);
    }
    return render::render_figure(held->scene, figure, format, scale, budget);
  });
  return py::bytes(bytes);
}

py::object animate_scene(const HeldScene& held, const py::object& out, std::optional<double> fps,
                         std::optional<double> duration, std::optional<int> frames, double scale, int threads) {
  const animate::Timeline timeline = animate::make_timeline(held.scene, animate::Overrides{fps, duration, frames});
  if (out.is_none()) {  // the animated SVG, in memory; Ctrl-C seen after each frame
    std::string svg;
    try {
      py::gil_scoped_release unlocked;
      svg = animate::animated_svg(held.scene, timeline, [](int) {
        if (interrupted_from_released()) throw animate::Cancelled{};
      });
    } catch (const animate::Cancelled&) {
      throw py::error_already_set();  // the KeyboardInterrupt PyErr_CheckSignals set
    }
    return py::str(svg);
  }
  animate::Request request;
  request.out = py::str(out).cast<std::string>();
  request.kind = animate::output_kind(request.out.string());
  request.scale = scale;
  request.progress = false;
  request.threads = std::clamp(threads, 1, 64);
  // Ctrl-C between frames: write_animation removes its temporaries and
  // throws Cancelled (the command line exits instead).
  request.cancelled = interrupted_from_released;
  const char* given = std::getenv("PITA_FFMPEG");  // the front end reads the environment, animate does not
  const char* search_path = std::getenv("PATH");
  request.ffmpeg = animate::find_ffmpeg(given ? std::optional<std::string_view>(given) : std::nullopt,
                                        search_path ? std::optional<std::string_view>(search_path) : std::nullopt);
  animate::check_total_work(held.scene, timeline, request);
  std::vector<std::filesystem::path> written;
  try {
    py::gil_scoped_release unlocked;
    written = animate::write_animation(held.scene, timeline, request);
  } catch (const animate::Cancelled&) {
    throw py::error_already_set();  // the KeyboardInterrupt PyErr_CheckSignals set
  }
  py::list paths;
  for (const auto& path : written) paths.append(path.string());
  return paths;
}

py::object measure(const HeldScene& held) {
  analysis::check_measure_work(held.scene);
  std::string text;
  {
    py::gil_scoped_release unlocked;
    text = analysis::measures_json(held.scene.path, analysis::measure_scene(held.scene));
  }
  return py::module_::import("json").attr("loads")(text);
}

py::object check(const HeldScene& held, const py::object& golden_dir, std::optional<double> number_tolerance,
                 std::optional<double> svg_tolerance, std::optional<int> pixel_tolerance,
                 std::optional<double> max_differing) {
  if (!held.file) {
    throw py::value_error(
        "check: a scene made from a dict has no file, and goldens are named after the file: "
        "write it to NAME.json and load_scene(\"NAME.json\")");
  }
  const auto within = [](const auto& value, double low, double high, const char* name) {
    if (value && !(*value >= low && *value <= high)) {
      throw py::value_error(fmt::format("{}: must be between {} and {} (got {})", name, low, high, *value));
    }
  };
  within(number_tolerance, 0.0, 1.0, "number_tolerance");
  within(svg_tolerance, 0.0, 1000.0, "svg_tolerance");
  within(pixel_tolerance, 0.0, 255.0, "pixel_tolerance");
  within(max_differing, 0.0, 1.0, "max_differing");
  // As `pita check`: the keywords, else the scene's "golden" field, else the defaults.
  const golden::Tolerances tolerances =
      golden::tolerances_of(held.scene, {number_tolerance, svg_tolerance, pixel_tolerance, max_differing});
  const std::filesystem::path folder = py::str(golden_dir).cast<std::string>();
  golden::SceneCheck result;
  {
    py::gil_scoped_release unlocked;
    result = golden::check_scene(*held.file, folder, tolerances);
  }
  const py::module_ collections = py::module_::import("collections");
  const py::object file_check = collections.attr("namedtuple")("FileCheck", "kind golden verdict detail");
  const py::object claim = collections.attr("namedtuple")("ClaimOutcome", "pointer says held measured");
  const py::object finding = collections.attr("namedtuple")("LintFinding", "check pointer message fix accepted");
  const py::object outcome =
      collections.attr("namedtuple")("CheckResult", "passes matches claims_hold legible files claims lint");
  py::list files, claims, lint;
  for (const golden::FileCheck& file : result.files) {
    const char* verdict = file.verdict == golden::Verdict::match     ? "match"
                          : file.verdict == golden::Verdict::differs ? "differs"
                                                                     : "missing";
    files.append(file_check(std::string(golden::suffix(file.kind)), file.golden.string(), verdict, file.detail));
  }
  for (const analysis::ClaimOutcome& c : result.claims) claims.append(claim(c.pointer, c.says, c.held, c.measured));
  for (const lint::Finding& f : result.lint.findings) {
    lint.append(finding(f.check, f.pointer, f.message, f.fix, !f.reason.empty()));
  }
  return outcome(result.passes(), result.matches(), result.claims_hold(), result.legible(), files, claims, lint);
}

// Raises the OSError of a scene file that cannot be read: Python's own
// subclass for its errno (FileNotFoundError, PermissionError,
// IsADirectoryError, ...), or OSError saying what it is (a FIFO, a device).
[[noreturn]] void raise_unreadable(const std::filesystem::path& path, const io::InputError& error, int number) {
  const std::string sentence = error.sentence("scene file");
  // OSError(errno, words, file) is the subclass of errno, with .filename;
  // without an errno, the words name the file (a .filename would print as
  // "[Errno None] None: FILE").
  const py::object raised =
      number != 0 ? py::reinterpret_borrow<py::object>(PyExc_OSError)(number, sentence, path.string())
                  : py::reinterpret_borrow<py::object>(PyExc_OSError)(fmt::format("{}: {}", path.string(), sentence));
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(raised.ptr())), raised.ptr());
  throw py::error_already_set();
}

// The errno of a file that could not be opened (io::InputError keeps only its
// words): opened again as io::InputFile opens it, 0 when it opens now.
int open_errno(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return errno;
  ::close(fd);
  return 0;
}

// A scene file read and checked without the GIL (a slow disk or a FIFO never
// freezes the other threads). A file that cannot be read is an OSError
// (raise_unreadable); one beyond the size limit, or a bad scene, SceneError.
scene::Scene read_scene_file(const std::filesystem::path& path) {
  if (const std::string& name = path.native(); name.find('\0') != std::string::npos) {
    // A ValueError, as Python's open() raises for it; the name is shown with
    // its NUL as \0 (a C string would end there).
    std::string shown;
    for (const char c : name) shown += c == '\0' ? std::string("\\0") : std::string(1, c);
    throw scene::SceneError(shown, "", "cannot read the scene file: its name holds a NUL byte");
  }
  std::optional<io::InputError> failure;
  int number = 0;
  {
    py::gil_scoped_release unlocked;
    std::string text;
    try {
      text = io::read_regular_file(path, scene::kMaxSceneFileBytes);
    } catch (const io::InputError& error) {
      failure.emplace(error);
      if (error.kind() == io::InputError::Kind::cannot_open) number = open_errno(path);
      if (error.kind() == io::InputError::Kind::not_regular) {
        std::error_code ignored;
        if (std::filesystem::is_directory(path, ignored)) number = EISDIR;
      }
    }
    if (!failure) return scene::parse_scene(text, path.string());
  }
  if (failure->kind() == io::InputError::Kind::too_large) {
    throw scene::SceneError(path.string(), "", failure->sentence("scene file"));  // a ValueError, as before
  }
  raise_unreadable(path, *failure, number);
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<HeldScene, std::shared_ptr<HeldScene>>(m, "Scene", R"(A scene (docs/reference/scene-format.md), read and
checked once. In a Jupyter notebook it shows its figure.)")
      .def_property_readonly(
          "path", [](const HeldScene& s) { return s.scene.path; }, "The file it was read from, or \"<dict>\".")
      .def_property_readonly("title", [](const HeldScene& s) { return s.scene.title; })
      .def_property_readonly("description", [](const HeldScene& s) { return s.scene.description; })
      .def_property_readonly(
          "kind", [](const HeldScene& s) { return std::string(scene::kind_name(s.scene.keys)); },
          "\"arrows\", \"points\", \"poses\" or \"poses3d\".")
      .def_property_readonly("method", [](const HeldScene& s) { return scene::method_id(s.scene.keys); })
      .def_property_readonly(
          "panels", [](const HeldScene& s) { return s.scene.panels.size(); },
          "How many panels the figure has (1 for a scene without \"panels\").")
      .def_property_readonly(
          "has_motion", [](const HeldScene& s) { return scene::has_motion_keys(s.scene.keys); },
          "False for a figure that needs no motion (a pose scene without poses).")
      .def(
          "motion", [](const HeldScene& s, std::optional<int> panel) { return hold_motion(s.scene, panel); },
          py::arg("panel") = py::none(),
          "The scene's own motion (or panel `panel`'s), built once, as pita.motion returns one.")
      .def("eval", &eval, py::arg("t") = py::none(), py::kw_only(), py::arg("samples") = py::none(),
           py::arg("panel") = py::none(), py::arg("method") = py::none(), py::arg("format") = py::none(),
           R"(The frames `pita eval` prints: at times t (a number or an array; outside the knots they
extrapolate), else at `samples` evenly spaced times over the knots (default: the scene's
"samples", else 9). panel: a panel's motion instead of the scene's own; method: another method.
As arrays (what pita.Motion returns), or with format="json" / "csv" as the text `pita eval`
prints, byte for byte.)")
      .def("render", &render_bytes, py::arg("format") = "svg", py::kw_only(), py::arg("scale") = 1.0,
           py::arg("at") = py::none(), py::arg("budget") = 1.0,
           R"(The figure as the bytes of an SVG, PNG or PDF file, as `pita render` writes it (scale: PNG
pixels per canvas pixel; at: the animation frame at scene time `at`, as `pita render --at`).)")
      .def("animate", &animate_scene, py::arg("out") = py::none(), py::kw_only(), py::arg("fps") = py::none(),
           py::arg("duration") = py::none(), py::arg("frames") = py::none(), py::arg("scale") = 1.0,
           py::arg("threads") = 1,
           R"(Plays the scene as `pita animate` does. Without `out`, returns the animated SVG as a str; with
`out`, writes it (OUT.svg, OUT.mp4 or OUT.webm through Debian's ffmpeg, or a folder of frames)
atomically and returns the paths written: complete, or not at all. Ctrl-C is seen between
frames: KeyboardInterrupt, with the temporaries removed and nothing written (threads: 1 to
64 frames drawn at once).)")
      .def("measure", &measure,
           R"(The goodness measures of every panel, as `pita measure --format json` prints them, as a dict.)")
      .def("check", &check, py::arg("golden_dir"), py::kw_only(), py::arg("number_tolerance") = py::none(),
           py::arg("svg_tolerance") = py::none(), py::arg("pixel_tolerance") = py::none(),
           py::arg("max_differing") = py::none(),
           R"(Compares the scene's fresh figures with its goldens in golden_dir/NAME/ and checks its claims
and lint, as `pita check` does. Returns CheckResult(passes, matches, claims_hold, legible,
files, claims, lint).)")
      .def("_repr_svg_",
           [](const HeldScene& s) { return render_bytes(s, "svg", 1.0, std::nullopt, 1.0).cast<std::string>(); })
      .def("_repr_png_", [](const HeldScene& s) { return render_bytes(s, "png", 1.0, std::nullopt, 1.0); })
      .def("__repr__", [](const HeldScene& s) {
        return fmt::format("<pita.Scene {} ({}, {}, {} panel{})>", s.scene.path,
                           std::string(scene::kind_name(s.scene.keys)), scene::method_id(s.scene.keys),
                           s.scene.panels.size(), s.scene.panels.size() == 1 ? "" : "s");
      });
  refuse_uninitialised<HeldScene>();

  m.def(
      "load_scene",
      [](const py::object& source) {
        auto held = std::make_shared<HeldScene>();
        if (py::isinstance<py::dict>(source)) {
          const std::string text =
              py::module_::import("json").attr("dumps")(source, py::arg("allow_nan") = false).cast<std::string>();
          py::gil_scoped_release unlocked;
          held->scene = scene::parse_scene(text, "<dict>");
        } else {
          const std::filesystem::path path = py::module_::import("os").attr("fspath")(source).cast<std::string>();
          held->scene = read_scene_file(path);
          held->file = std::filesystem::absolute(path);  // check() reads it again, wherever the cwd is then
        }
        return held;
      },
      py::arg("source"),
      R"(Reads and checks a scene: a path (str or os.PathLike) to a scene file, or a dict in the same
format. Raises pita.SceneError (a ValueError) with .file, .pointer (JSON Pointer) and .reason,
and .line and .column for malformed JSON; a file that cannot be read raises an OSError naming it
(FileNotFoundError, PermissionError, IsADirectoryError; a FIFO or a device: OSError saying what
it is). The file is read and checked without the GIL. Images of the scene are found relative to its folder as the path
spells it: give an absolute path if the working directory will change.)");
}

}  // namespace pita::python
