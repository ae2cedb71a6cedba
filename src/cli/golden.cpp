#include "cli/golden.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/failure.hpp"
#include "cli/scene_jobs.hpp"
#include "golden/check.hpp"
#include "golden/golden_file.hpp"
#include "golden/report.hpp"
#include "io/input_file.hpp"
#include "io/output_file.hpp"
#include "render/panel_drawing.hpp"
#include "scene/image_file.hpp"
#include "scene/scene.hpp"

namespace pita::cli {

namespace {

namespace fs = std::filesystem;

// The scenes named, or every scenes/*.json of the working directory.
std::vector<fs::path> scenes_of(const GoldenOptions& options) {
  std::vector<fs::path> paths(options.scene_paths.begin(), options.scene_paths.end());
  if (paths.empty()) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator("scenes", error)) {
      if (entry.path().extension() == ".json") paths.push_back(entry.path());
    }
    std::sort(paths.begin(), paths.end());
  }
  return paths;
}

// The command line's tolerances, else the scene's "golden" field, else the defaults.
golden::Tolerances tolerances_of(const GoldenOptions& o, const fs::path& scene_path) {
  return golden::tolerances_of(scene::load_scene(scene_path),
                               {o.number_tolerance, o.svg_tolerance, o.pixel_tolerance, o.max_differing});
}

void add_common(CLI::App* command, GoldenOptions& o) {
  command->add_option("SCENE", o.scene_paths, "Scene files (default: every scenes/*.json)");
  command->add_option("--golden", o.golden_dir, "Golden directory, mirroring scenes/")
      ->capture_default_str()
      ->type_name("DIR");
  add_scene_jobs_option(*command, o.jobs);
}

}  // namespace

std::shared_ptr<GoldenOptions> setup_check(CLI::App& app) {
  auto o = std::make_shared<GoldenOptions>();
  CLI::App* check = app.add_subcommand("check", "Compare each scene's figure with its goldens");
  add_common(check, *o);
  check
      ->add_option("--report", o->report_dir,
                   "Write DIR/index.html with the expected, actual and diff images of each mismatch")
      ->type_name("DIR");
  check
      ->add_option("--number-tolerance", o->number_tolerance,
                   fmt::format("Largest difference of a drawn number, relative to its panel's "
                               "extent (default {:g})",
                               golden::kDefaultNumberTolerance))
      ->check(CLI::Range(0.0, 1.0))
      ->type_name("X");
  check
      ->add_option(
          "--svg-tolerance", o->svg_tolerance,
          fmt::format("Largest difference of an SVG number, in pixels (default {:g})", golden::kDefaultSvgTolerance))
      ->check(CLI::Range(0.0, 1000.0))
      ->type_name("PX");
  check
      ->add_option("--pixel-tolerance", o->pixel_tolerance,
                   fmt::format("A PNG pixel differs when a channel differs by more than N levels "
                               "of 255 (default {})",
                               golden::kDefaultChannelTolerance))
      ->check(CLI::Range(0, 255))
      ->type_name("N");
  check
      ->add_option("--max-differing", o->max_differing,
                   fmt::format("Largest share of differing PNG pixels that still matches, 0-1 "
                               "(default {:g})",
                               golden::kDefaultDifferingShare))
      ->check(CLI::Range(0.0, 1.0))
      ->type_name("SHARE");
  check->footer(R"(
Each scene is rendered in memory and compared with golden/<name>/<name>.data.json
(every drawn number, relative tolerance), .svg (its geometry, parsed numbers with an
absolute tolerance) and .png (per-pixel tolerance and a share of differing pixels).
A scene may set its own tolerances ("golden": {"number_tolerance", "svg_tolerance",
"pixel_tolerance", "max_differing"}); the command line overrides them.
A scene without goldens fails. Exit codes: 0 all match, 1 a figure differs or has no
golden, 2 a bad scene or an unreadable golden.

Examples:
  pita check                               every scene of scenes/ against golden/
  pita check scenes/fig13-knot-ratio.json --report check-report
)");
  return o;
}

std::shared_ptr<GoldenOptions> setup_update_goldens(CLI::App& app) {
  auto o = std::make_shared<GoldenOptions>();
  CLI::App* update = app.add_subcommand("update-goldens", "Write the goldens of scenes (the only way goldens change)");
  add_common(update, *o);
  update->footer(R"(
Renders each scene and writes golden/<name>/<name>.{data.json,svg,png}, printing for
each file whether it is new, unchanged or changed, and by how much. Review the
changes (git diff, the PNGs) before committing them, and say why they changed.
)");
  return o;
}

namespace {

// What pita check read: the scenes, their images and their goldens (which
// the report must not replace).
std::vector<fs::path> check_inputs(const std::vector<fs::path>& scenes,
                                   const std::vector<golden::ReportEntry>& report) {
  std::vector<fs::path> inputs(scenes.begin(), scenes.end());
  for (const golden::ReportEntry& entry : report) {
    for (const golden::FileCheck& file : entry.check.files) inputs.push_back(file.golden);
  }
  for (const fs::path& scene : scenes) {
    try {
      for (const fs::path& image : scene::image_files(scene::load_scene(scene))) inputs.push_back(image);
    } catch (const std::exception&) {
      // a bad scene: its error is in the report, and it drew no image
    }
  }
  return inputs;
}

}  // namespace

ExitCode run_check(const GoldenOptions& options) {
  const std::vector<fs::path> scenes = scenes_of(options);
  if (scenes.empty()) {
    std::cerr << "pita: check: no scenes given and no scenes/*.json here\n";
    return ExitCode::bad_input;
  }
  // The goldens change only by update-goldens: a report among them could replace one.
  if (options.report_dir && io::within_folder(*options.report_dir, options.golden_dir)) {
    std::cerr << fmt::format(
        "pita: --report {}: the report would be written among the goldens ({}), which only "
        "pita update-goldens writes: give another folder\n",
        *options.report_dir, options.golden_dir);
    return ExitCode::bad_input;
  }
  ExitCode result = ExitCode::success;
  std::vector<golden::ReportEntry> report;
  // Each scene checked on a worker thread, its verdict printed here, in order.
  struct Checked {
    golden::ReportEntry entry;
    ExitCode code = ExitCode::success;
  };
  for_each_scene(
      scenes.size(), scene_jobs(options.jobs),
      [&](std::size_t i) {
        const fs::path& scene = scenes[i];
        Checked checked;
        checked.entry.check.scene_path = scene.string();
        checked.entry.check.name = golden::scene_name(scene);
        try {
          checked.entry.check = golden::check_scene(scene, options.golden_dir, tolerances_of(options, scene));
        } catch (...) {
          const Failure failure = current_failure(scene.string());
          checked.entry.error = failure.message;
          checked.code = failure.code;
        }
        return checked;
      },
      [&](std::size_t i, Checked checked) {
        const fs::path& scene = scenes[i];
        golden::ReportEntry& entry = checked.entry;
        result = worse(result, checked.code);
        if (!entry.error.empty()) {
          std::cerr << "pita: " << entry.error << '\n';
        } else if (entry.check.passes()) {
          std::cout << "ok    " << scene.string()
                    << (entry.check.claims.empty() ? std::string()
                                                   : fmt::format(" ({} claims hold)", entry.check.claims.size()))
                    << '\n';
        } else {
          result = worse(result, ExitCode::golden_mismatch);
          std::cerr << "FAIL  " << scene.string() << '\n';
          for (const golden::FileCheck& f : entry.check.files) {
            if (f.verdict == golden::Verdict::match) continue;
            std::cerr << "      " << f.golden.string() << ": " << f.detail << '\n';
          }
          for (const analysis::ClaimOutcome& c : entry.check.claims) {
            if (c.held) continue;
            std::cerr << "      " << c.pointer << ": claim failed: \"" << c.says << "\": " << c.measured << '\n';
          }
          for (const lint::Finding& f : entry.check.lint.findings) {
            if (f.reason.empty()) std::cerr << "      lint: " << lint::describe(f) << '\n';
          }
        }
        report.push_back(std::move(entry));
      });
  if (options.report_dir) {
    try {
      golden::write_report(*options.report_dir, report, check_inputs(scenes, report));
      std::cerr << "report: " << (fs::path(*options.report_dir) / "index.html").string() << '\n';
    } catch (...) {
      const Failure failure = current_failure("--report " + *options.report_dir);
      std::cerr << "pita: --report " << *options.report_dir << ": " << failure.message << '\n';
      return worse(result, failure.code);
    }
  }
  return result;
}

namespace {

// A golden as update-goldens found it: what to write (unless unchanged) and
// what it prints of it.
struct UpdatedFile {
  fs::path path;
  std::optional<std::string> bytes;  // to write, unless unchanged
  std::string status;
};

// A scene's goldens, rendered and compared on a worker thread.
struct UpdatedScene {
  std::vector<UpdatedFile> files;
  std::optional<Failure> failure;
};

// The golden at `path` against `bytes`, exactly, to say by how much it changed.
std::string golden_status(const golden::GoldenFile& file, const fs::path& path, const std::string& bytes) {
  golden::Tolerances exact;
  exact.numbers = 0.0;
  exact.svg = 0.0;
  exact.image = {0, 0.0};
  try {
    const golden::FileCheck c = golden::compare_file(file.kind, path, bytes, exact);
    if (c.verdict == golden::Verdict::missing) return "new";
    if (c.expected == bytes) return "unchanged";
    return "changed: " + c.detail;
  } catch (const golden::GoldenPathError&) {
    throw;  // a link, FIFO or device: never written through (exit 2)
  } catch (const golden::GoldenError& e) {
    return std::string("replaced an unreadable golden (") + e.what() + ")";
  }
}

// Renders a scene's goldens and compares each with the one in --golden.
UpdatedScene update_scene(const GoldenOptions& options, const fs::path& scene) {
  UpdatedScene updated;
  try {
    const golden::Outputs outputs = golden::render_outputs(scene);
    const std::string name = golden::scene_name(scene);
    for (const golden::GoldenFile& file : golden::golden_files(outputs)) {
      const std::string& bytes = *file.bytes;
      const fs::path path = golden::golden_path(options.golden_dir, name, file.suffix);
      std::string status = golden_status(file, path, bytes);
      std::optional<std::string> to_write;
      if (status != "unchanged") {
        golden::check_golden_folder(path);  // not a link out of --golden
        to_write = bytes;
      }
      updated.files.push_back({path, std::move(to_write), std::move(status)});
    }
  } catch (...) {
    updated.failure = current_failure(scene.string());
  }
  return updated;
}

// Writes what changed of a scene's goldens and prints each; its failure, if any.
std::optional<Failure> write_updated(const fs::path& scene, const UpdatedScene& updated) {
  if (updated.failure) return updated.failure;
  try {
    for (const UpdatedFile& file : updated.files) {
      if (file.bytes) {
        fs::create_directories(file.path.parent_path());
        io::write_file_atomically(file.path, *file.bytes);
      }
      std::cout << file.path.string() << ": " << file.status << '\n';
    }
  } catch (...) {
    return current_failure(scene.string());
  }
  return std::nullopt;
}

}  // namespace

ExitCode run_update_goldens(const GoldenOptions& options) {
  const std::vector<fs::path> scenes = scenes_of(options);
  if (scenes.empty()) {
    std::cerr << "pita: update-goldens: no scenes given and no scenes/*.json here\n";
    return ExitCode::bad_input;
  }
  ExitCode result = ExitCode::success;
  // Each scene rendered and compared on a worker thread; what changed
  // written and printed here, scene after scene.
  for_each_scene(
      scenes.size(), scene_jobs(options.jobs), [&](std::size_t i) { return update_scene(options, scenes[i]); },
      [&](std::size_t i, const UpdatedScene& updated) {
        if (const std::optional<Failure> failure = write_updated(scenes[i], updated)) {
          std::cerr << "pita: " << failure->message << '\n';
          result = worse(result, failure->code);
        }
      });
  return result;
}

}  // namespace pita::cli
