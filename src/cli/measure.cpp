#include "cli/measure.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <vector>

#include <CLI/CLI.hpp>

#include "analysis/measure.hpp"
#include "analysis/measure_report.hpp"
#include "cli/failure.hpp"
#include "scene/scene.hpp"

namespace pita::cli {

std::shared_ptr<MeasureOptions> setup_measure(CLI::App& app) {
  auto options = std::make_shared<MeasureOptions>();
  CLI::App* measure = app.add_subcommand(
      "measure",
      "Print goodness measures of a scene's motions: discrepancy, path length, turning and inflections, winding "
      "range, overreaction, pops, ARA and area monotonicity");
  measure->footer(R"(
For each panel (or the scene itself): the discrepancy E (PITA Eq. 47) of each frame against the
previous frame, the steady average of its neighbours and the method's own prediction (Sec. 6.1);
length, total turning and inflections of the paths of p and q; the winding range; the overreaction gain of
every keyframe parameter (A.p.x, A.p.y, A.q.x, A.q.y, A.m, A.w, A.t, B..., Sec. 6.4) and pops
under a 1e-9 tweak (Sec. 4.7); for pose scenes ARA (SAM Sec. 2.4) and area monotonicity.
docs/reference/measure.md "pita measure" gives each number's meaning and units.

Examples:
  pita measure scenes/fig01-eight-pitas.json
  pita measure scenes/fig12-pops.json --format json
  pita measure scenes/sam-fig02-linear-and-sam.json --format csv

Exit codes: 0 success (a panel whose motion does not exist is reported as such), 2 bad input
or usage, 3 the report could not be written to standard output, 4 an internal error.
)");
  measure->add_option("SCENE", options->scene_path, "Scene file (JSON)")->required();
  measure->add_option("--format", options->format, "Output format")
      ->check(CLI::IsMember({"md", "csv", "json"}))
      ->type_name("FORMAT")
      ->capture_default_str();
  return options;
}

ExitCode run_measure(const MeasureOptions& options) {
  try {
    const scene::Scene scene = scene::load_scene(options.scene_path);
    analysis::check_measure_work(scene);
    const std::vector<analysis::MotionMeasures> all = analysis::measure_scene(scene);
    const std::string text = options.format == "json"  ? analysis::measures_json(scene.path, all)
                             : options.format == "csv" ? analysis::measures_csv(all)
                                                       : analysis::measures_markdown(scene.path, all);
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
      std::cerr << "pita: cannot write the measures to standard output (" << std::strerror(errno) << ")\n";
      return ExitCode::failure;
    }
    return ExitCode::success;
  } catch (...) {
    const Failure failure = current_failure(options.scene_path);
    std::cerr << "pita: " << failure.message << '\n';
    return failure.code;
  }
}

}  // namespace pita::cli
