// The legibility lint (`pita lint`, and `pita check`): what a reader of a
// figure would stumble on, found from the figure's geometry before it is
// painted (lint/geometry.hpp): text on text, text or a legend over data,
// things cut off at a panel's edge, small content, frames too short to see,
// series that share a colour. The checks are the rows of
// scene::kLintChecks; a scene accepts a finding, with its reason, under
// "lint": {"allow": [...]} (docs/reference/lint.md "Lint").
#pragma once

#include <string>
#include <vector>

#include "analysis/claims.hpp"
#include "motion/stage.hpp"
#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::lint {

struct Finding {
  std::string check;       // a name of scene::kLintChecks
  std::string pointer;     // the layer, title or panel it names ("" = the scene)
  std::string message;     // what is wrong, in canvas pixels
  std::string fix;         // what to change in the scene: a field, or "lint" to accept it
  std::string reason;      // why the scene accepts it ("" = not accepted)
  std::string allowed_at;  // the accepting entry, "/lint/allow/0"
};

struct Report {
  std::vector<Finding> findings;           // in the order of the checks
  std::vector<std::string> unused_allows;  // entries of "allow" that accept nothing ("/lint/allow/2")
  bool clean() const;                      // every finding accepted
  std::size_t accepted() const;
};

// The lint of a figure built from the stage's motions (render::build_figure),
// given its claims as analysis::check_claims measured them on those motions
// (pita check measures them once for both; empty when they cannot be measured).
Report lint_figure(const motion::Stage& stage, const render::Figure& figure,
                   const std::vector<analysis::ClaimOutcome>& claims);

// "/layers/3: text-over-data: the label ...; fix: ..." (and "(accepted: REASON)").
std::string describe(const Finding& finding);

}  // namespace pita::lint
