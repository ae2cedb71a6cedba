// The claims of a scene (scene/claim.hpp; docs/reference/check.md "Claims") measured on the
// motions the stage built, the same ones the figure draws: `pita check`
// fails on a claim that does not hold, `pita render` warns.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analysis/claim_measurer.hpp"
#include "motion/stage.hpp"
#include "scene/claim.hpp"

namespace pita::analysis {

struct ClaimOutcome {
  std::string pointer;  // "/claims/2"
  std::string says;     // the claim in words
  bool held = false;
  // What was measured and compared: "scale-step of panel 3 (P8 Lo-Pe) = 0.112, below 0.405
  // (scale-step of panel 0 (P1 Pa-Ca))".
  std::string measured;
  double value = std::numeric_limits<double>::quiet_NaN();  // the measure's value compared (|value| for "absolute")
};

// Every claim of the stage's scene, in order. Throws as Measurer::value.
std::vector<ClaimOutcome> check_claims(const motion::Stage& stage);

// Only the claims `which` chooses are measured (`pita lint` needs a few of
// them); the others are outcomes that did not hold, with a NaN value and
// "not measured". In order, one per claim, as check_claims.
std::vector<ClaimOutcome> check_claims(const motion::Stage& stage,
                                       const std::function<bool(const scene::Claim&)>& which);

// What the claims cost, in frames of a plain method (motion::frame_cost):
// the measures of each panel a claim names (what `pita check` budgets).
double claims_cost(const scene::Scene& scene);

}  // namespace pita::analysis
