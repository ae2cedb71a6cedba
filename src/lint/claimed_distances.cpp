// The claims a figure must draw large enough to see (lint/geometry.hpp,
// the small-feature check of lint/checks.cpp).
#include <cmath>
#include <exception>
#include <variant>

#include "analysis/claims.hpp"
#include "lint/geometry.hpp"

namespace pita::lint {

std::vector<ClaimedDistance> claimed_distances(const motion::Stage& stage) {
  const scene::Scene& scene = stage.scene();
  std::vector<ClaimedDistance> out;
  analysis::Measurer measurer(stage);
  for (const scene::Claim& claim : scene.claims) {
    if (!std::holds_alternative<scene::Above>(claim.test) || !scene::is_drawn_distance(claim.measure.kind)) continue;
    if (!std::holds_alternative<scene::KeyframeKeys>(scene.panels.at(claim.panel).keys)) continue;
    double value = 0.0;
    try {
      value = measurer.value(claim.panel, claim.measure, claim.pointer, claim.layer);
    } catch (const std::exception&) {
      continue;  // pita check says why the claim cannot be measured
    }
    if (!std::isfinite(value)) continue;
    // A claim that does not hold fails on its own (pita check): the lint
    // speaks of what a claim that holds shows.
    const scene::ClaimBound& bound = std::get<scene::Above>(claim.test).bound;
    const auto* operand = std::get_if<scene::ClaimOperand>(&bound);
    try {
      const double least =
          operand == nullptr
              ? std::get<double>(bound)
              : operand->times * measurer.value(operand->panel, operand->measure, claim.pointer) + operand->plus;
      if (!(value > least)) continue;
    } catch (const std::exception&) {
      continue;
    }
    out.push_back({claim.pointer, claim.says, claim.panel, claim.measure.panel, value});
  }
  return out;
}

}  // namespace pita::lint
