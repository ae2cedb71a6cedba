// The claims a figure must draw large enough to see (lint/geometry.hpp,
// the small-feature check of lint/checks.cpp).
#include <cmath>
#include <variant>

#include "analysis/claims.hpp"
#include "lint/geometry.hpp"

namespace pita::lint {

bool is_claimed_distance(const scene::Scene& scene, const scene::Claim& claim) {
  return std::holds_alternative<scene::Above>(claim.test) && scene::is_drawn_distance(claim.measure.kind) &&
         std::holds_alternative<scene::KeyframeKeys>(scene.panels.at(claim.panel).keys);
}

std::vector<ClaimedDistance> claimed_distances(const motion::Stage& stage,
                                               const std::vector<analysis::ClaimOutcome>& claims) {
  const scene::Scene& scene = stage.scene();
  std::vector<ClaimedDistance> out;
  for (std::size_t k = 0; k < scene.claims.size() && k < claims.size(); ++k) {
    const scene::Claim& claim = scene.claims[k];
    if (!is_claimed_distance(scene, claim)) continue;
    // A claim that does not hold fails on its own (pita check): the lint
    // speaks of what a claim that holds shows.
    if (!claims[k].held || !std::isfinite(claims[k].value)) continue;
    out.push_back({claim.pointer, claim.says, claim.panel, claim.measure.panel, claims[k].value});
  }
  return out;
}

}  // namespace pita::lint
