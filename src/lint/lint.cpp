#include "lint/lint.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "lint/checks.hpp"
#include "lint/geometry.hpp"

namespace pita::lint {

namespace {

bool accepts(const scene::LintAllow& allow, const Finding& finding) {
  if (allow.check != finding.check) return false;
  if (allow.pointer.empty() || allow.pointer == finding.pointer) return true;
  return finding.pointer.starts_with(allow.pointer + "/");  // a panel's entry covers its layers
}

}  // namespace

bool Report::clean() const {
  return std::all_of(findings.begin(), findings.end(), [](const Finding& f) { return !f.reason.empty(); });
}

std::size_t Report::accepted() const {
  return static_cast<std::size_t>(
      std::count_if(findings.begin(), findings.end(), [](const Finding& f) { return !f.reason.empty(); }));
}

Report lint_figure(const motion::Stage& stage, const render::Figure& figure,
                   const std::vector<analysis::ClaimOutcome>& claims) {
  const scene::Scene& scene = stage.scene();
  FigureGeometry geometry = figure_geometry(scene, figure);
  geometry.claimed = claimed_distances(stage, claims);
  Report report;
  for (const Check check : check_functions()) check(geometry, scene.lint, report.findings);
  std::vector<bool> used(scene.lint.allow.size(), false);
  for (Finding& finding : report.findings) {
    for (std::size_t k = 0; k < scene.lint.allow.size(); ++k) {
      if (!accepts(scene.lint.allow[k], finding)) continue;
      finding.reason = scene.lint.allow[k].reason;
      finding.allowed_at = scene.lint.allow[k].at;
      used[k] = true;
      break;
    }
  }
  for (std::size_t k = 0; k < used.size(); ++k) {
    if (!used[k]) report.unused_allows.push_back(scene.lint.allow[k].at);
  }
  return report;
}

std::string describe(const Finding& finding) {
  return fmt::format(
      "{}: {}: {}; fix: {}{}", finding.pointer.empty() ? "(the scene)" : finding.pointer, finding.check,
      finding.message, finding.fix,
      finding.reason.empty() ? "" : fmt::format(" (accepted by {}: {})", finding.allowed_at, finding.reason));
}

}  // namespace pita::lint
