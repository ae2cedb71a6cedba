#include "analysis/claims.hpp"

#include <cmath>
#include <limits>
#include <set>

#include <fmt/format.h>

#include "scene/limits.hpp"

namespace pita::analysis {

namespace {

using scene::MeasureKind;

std::string number(double x) { return std::isnan(x) ? std::string("undefined") : fmt::format("{:.4g}", x); }

}  // namespace

namespace {

struct Bound {
  double value = 0.0;
  std::string text;  // "0.405 (scale-step of panel 0 (P1 Pa-Ca))", or "1.571"
};

Bound bound_of(Measurer& measurer, const motion::Stage& stage, const scene::ClaimBound& bound,
               const std::string& pointer, bool absolute) {
  if (const double* x = std::get_if<double>(&bound)) return {*x, number(*x)};
  const scene::ClaimOperand& operand = std::get<scene::ClaimOperand>(bound);
  double x = measurer.value(operand.panel, operand.measure, pointer);
  if (absolute) x = std::abs(x);
  const double value = operand.times * x + operand.plus;
  std::string text = fmt::format("{} of {}", operand.measure.text, panel_name(stage, operand.panel));
  if (operand.times != 1.0) text = fmt::format("{} x {}", number(operand.times), text);
  if (operand.plus != 0.0)
    text += fmt::format(" {} {}", operand.plus < 0.0 ? "-" : "+", number(std::abs(operand.plus)));
  return {value, fmt::format("{} ({})", number(value), text)};
}

ClaimOutcome check_claim(Measurer& measurer, const motion::Stage& stage, const scene::Claim& claim) {
  double value = measurer.value(claim.panel, claim.measure, claim.pointer + "/measure", claim.layer);
  if (claim.absolute) value = std::abs(value);
  ClaimOutcome outcome{claim.pointer, claim.says, false, {}, value};
  const std::string left = fmt::format(
      "{}{}{} of {}{} = {}", claim.absolute ? "|" : "", claim.measure.text, claim.absolute ? "|" : "",
      claim.layer ? fmt::format("layer {} of ", *claim.layer) : "", panel_name(stage, claim.panel), number(value));
  std::visit(
      [&](const auto& test) {
        using Test = std::decay_t<decltype(test)>;
        if constexpr (std::is_same_v<Test, scene::Below> || std::is_same_v<Test, scene::Above>) {
          constexpr bool below = std::is_same_v<Test, scene::Below>;
          const std::string at = claim.pointer + (below ? "/below" : "/above");
          const Bound bound = bound_of(measurer, stage, test.bound, at + "/measure", claim.absolute);
          outcome.held = below ? value < bound.value : value > bound.value;  // false for NaN
          outcome.measured =
              fmt::format("{}, {}{} {}", left, outcome.held ? "" : "not ", below ? "below" : "above", bound.text);
        } else if constexpr (std::is_same_v<Test, scene::Near>) {
          const Bound target = bound_of(measurer, stage, test.target, claim.pointer + "/near/measure", claim.absolute);
          outcome.held = std::abs(value - target.value) <= test.within;
          outcome.measured =
              fmt::format("{}, {}within {} of {}", left, outcome.held ? "" : "not ", number(test.within), target.text);
        } else {
          outcome.held = (value != 0.0) == test.yes;
          outcome.measured = fmt::format("{}: {}", left, value != 0.0 ? "yes" : "no");
        }
      },
      claim.test);
  return outcome;
}

}  // namespace

std::vector<ClaimOutcome> check_claims(const motion::Stage& stage) {
  return check_claims(stage, [](const scene::Claim&) { return true; });
}

std::vector<ClaimOutcome> check_claims(const motion::Stage& stage,
                                       const std::function<bool(const scene::Claim&)>& which) {
  const scene::Scene& scene = stage.scene();
  if (scene.claims.empty()) return {};
  const double work = claims_cost(scene);
  if (work > scene::kMaxEvalWork) {
    throw scene::SceneError(scene.path, "/claims",
                            fmt::format("measuring the claims costs about {:.3g} frames of a method, above the limit "
                                        "of {:.0g}: fewer claims on measures of the keyframes' tweaks, or fewer "
                                        "keyframes",
                                        work, scene::kMaxEvalWork));
  }
  Measurer measurer(stage);
  std::vector<ClaimOutcome> outcomes;
  for (const scene::Claim& claim : stage.scene().claims) {
    if (!which(claim)) {
      outcomes.push_back({claim.pointer, claim.says, false, "not measured", std::numeric_limits<double>::quiet_NaN()});
      continue;
    }
    try {
      outcomes.push_back(check_claim(measurer, stage, claim));
    } catch (const motion::NoMotion& error) {
      // The panels' own motions first: a panel without one is that panel's
      // fault. Their motions existing, a frame missing where the claim asks
      // (a time far outside the knots) is the claim's.
      if (stage.has_motion(claim.panel)) (void)stage.motion(claim.panel);
      if (claim.measure.panel && stage.has_motion(*claim.measure.panel)) (void)stage.motion(*claim.measure.panel);
      throw scene::SceneError(scene.path, claim.pointer + "/measure",
                              fmt::format("\"{}\" cannot be measured: {}", claim.measure.text, error.reason()));
    }
  }
  return outcomes;
}

double claims_cost(const scene::Scene& scene) {
  std::set<std::size_t> measured, stepped;  // panels whose measures (frame steps) are counted
  double cost = 0.0;
  const auto add = [&](std::size_t panel, const scene::MeasureName& measure) {
    const scene::Panel& p = scene.panels.at(panel);
    switch (source_of(measure.kind)) {
      case Source::frame_steps:  // the drawn frames, once per panel
        if (stepped.insert(panel).second) cost += (kScaleSamples + p.samples) * motion::frame_cost(p);
        break;
      case Source::comparison:  // both panels' frames
        cost += (kHandleShiftSamples + 2 * kFrameDistanceSamples) * motion::frame_cost(p);
        break;
      case Source::measures:  // the panel's measures (measure_panel), once per panel
      case Source::property:
        if (measured.insert(panel).second) cost += measure_cost(p);
        break;
    }
  };
  for (const scene::Claim& claim : scene.claims) {
    add(claim.panel, claim.measure);
    const scene::ClaimBound* bound = std::visit(
        [](const auto& test) -> const scene::ClaimBound* {
          using Test = std::decay_t<decltype(test)>;
          if constexpr (std::is_same_v<Test, scene::Near>) {
            return &test.target;
          } else if constexpr (std::is_same_v<Test, scene::Is>) {
            return nullptr;
          } else {
            return &test.bound;
          }
        },
        claim.test);
    if (bound == nullptr) continue;
    if (const auto* operand = std::get_if<scene::ClaimOperand>(bound)) add(operand->panel, operand->measure);
  }
  return cost;
}

}  // namespace pita::analysis
