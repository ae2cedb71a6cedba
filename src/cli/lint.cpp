#include "cli/lint.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "analysis/claims.hpp"
#include "cli/failure.hpp"
#include "lint/geometry.hpp"
#include "lint/lint.hpp"
#include "motion/no_motion.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::cli {

namespace {

std::string check_list() {
  std::string out;
  for (const scene::LintCheckInfo& check : scene::kLintChecks) {
    out += fmt::format("  {:<17} {}\n", check.name, check.what);
  }
  return out;
}

nlohmann::json finding_json(const lint::Finding& f) {
  nlohmann::json out = {{"check", f.check}, {"pointer", f.pointer}, {"message", f.message}, {"fix", f.fix}};
  if (!f.reason.empty()) out["accepted"] = {{"by", f.allowed_at}, {"reason", f.reason}};
  return out;
}

bool write_stdout(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
    std::cerr << "pita: cannot write the lint's findings to standard output (" << std::strerror(errno) << ")\n";
    return false;
  }
  return true;
}

}  // namespace

std::shared_ptr<LintOptions> setup_lint(CLI::App& app) {
  auto options = std::make_shared<LintOptions>();
  const scene::LintSettings defaults;
  CLI::App* lint = app.add_subcommand(
      "lint",
      "Check that each scene's figure is legible: no text over text or data, nothing cut off, no tiny "
      "content or frames, no two series in one colour");
  lint->footer(fmt::format(R"(
The lint looks at the figure as `pita render` would draw it, in canvas pixels, before painting.
Its checks:
{}
A scene accepts a finding, with the reason, under "lint": {{"allow": [{{"check": "text-over-data",
"pointer": "/layers/3", "reason": "..."}}]}}; "min_content_share" (default {}), "min_motion_share"
(default {}), "min_frame_pixels" (default {}), "min_feature_pixels" (default {}) and
"max_hidden_share" (default {}) set its thresholds (docs/reference/lint.md "Lint"). Each finding
says what to change in the scene ("fix: ..."). `pita check` runs the lint too.

Examples:
  pita lint scenes/*.json
  pita lint scenes/fig12-pops.json --format json

Exit codes: 0 every finding accepted, 1 a finding is not, 2 bad input or usage, 3 the findings
could not be written to standard output, 4 an internal error.
)",
                           check_list(), defaults.min_content_share, defaults.min_motion_share,
                           defaults.min_frame_pixels, defaults.min_feature_pixels, defaults.max_hidden_share));
  lint->add_option("SCENE", options->scene_paths, "Scene files (JSON)")->required();
  lint->add_option("--format", options->format, "Output format")
      ->check(CLI::IsMember({"text", "json"}))
      ->type_name("FORMAT")
      ->capture_default_str();
  return options;
}

ExitCode run_lint(const LintOptions& options) {
  ExitCode code = ExitCode::success;
  nlohmann::json all = nlohmann::json::array();
  for (const std::string& path : options.scene_paths) {
    try {
      const scene::Scene scene = scene::load_scene(path);
      const motion::Stage stage(scene);
      // Claims that cannot be measured are pita check's to report: the lint goes on without them.
      std::vector<analysis::ClaimOutcome> claims;
      try {
        // Only those the small-feature check reads: measuring every claim is pita check's.
        claims = analysis::check_claims(
            stage, [&](const scene::Claim& claim) { return lint::is_claimed_distance(scene, claim); });
      } catch (const scene::SceneError&) {
      } catch (const motion::NoMotion&) {
      }
      const lint::Report report = lint::lint_figure(stage, render::build_figure(stage), claims);
      if (!report.clean()) code = worse(code, ExitCode::golden_mismatch);
      if (options.format == "json") {
        nlohmann::json findings = nlohmann::json::array();
        for (const lint::Finding& f : report.findings) findings.push_back(finding_json(f));
        all.push_back({{"scene", path},
                       {"clean", report.clean()},
                       {"findings", findings},
                       {"unused_allows", report.unused_allows}});
        continue;
      }
      std::string text;
      for (const lint::Finding& f : report.findings) {
        if (f.reason.empty()) text += fmt::format("{}: {}\n", path, lint::describe(f));
      }
      for (const std::string& at : report.unused_allows) {
        text += fmt::format("{}: {}: note: this accepted finding no longer occurs (remove it)\n", path, at);
      }
      const std::size_t open = report.findings.size() - report.accepted();
      text += open == 0 ? fmt::format("{}: ok ({} findings accepted)\n", path, report.accepted())
                        : fmt::format("{}: {} findings ({} accepted)\n", path, open, report.accepted());
      if (!write_stdout(text)) return ExitCode::failure;
    } catch (...) {
      const Failure failure = current_failure(path);
      std::cerr << "pita: " << failure.message << '\n';
      code = worse(code, failure.code);
    }
  }
  if (options.format == "json" && !write_stdout(all.dump(2) + "\n")) return ExitCode::failure;
  return code;
}

}  // namespace pita::cli
