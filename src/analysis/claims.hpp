// The claims of a scene (scene/claim.hpp; docs/reference/check.md "Claims") measured on the
// motions the stage built, the same ones the figure draws: `pita check`
// fails on a claim that does not hold, `pita render` warns.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/frame_steps.hpp"
#include "analysis/measure.hpp"
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
};

// The value a claim compares of a measure (docs/reference/check.md "Claims"): for a name with
// several numbers the largest ("discrepancy-max": of the three predictors;
// "path-length", "turning": of p; "gain:B.q": of B.q.x and B.q.y);
// "winding-range" its width; "overreaction" the largest gain; "pop" 1 or 0;
// "area" the excursion against the trend (0 when monotone). NaN when the
// measure is undefined (an angle to a vanishing vector).
//
// Measures and frame steps of a panel are computed once and kept: one
// Measurer serves every claim of a stage.
class Measurer {
 public:
  explicit Measurer(const motion::Stage& stage);
  // Throws scene::SceneError at `pointer` when the panel has no such number
  // (a measure of keyframes on a panel of points, a parameter no keyframe
  // has), motion::NoMotion when the panel has no motion. With `layer`, a
  // frame-distance measures the motion that layer of the panel draws.
  double value(std::size_t panel, const scene::MeasureName& measure, const std::string& pointer,
               std::optional<std::size_t> layer = std::nullopt);

 private:
  const MotionMeasures& measures(std::size_t panel);
  // The measures of the panel's motion (measure_panel), kept: discrepancy,
  // paths, windings, reactions, pops; ARA, area and velocity jumps of poses.
  double measured_value(std::size_t panel, const scene::MeasureName& measure, const std::string& pointer);
  // Throws the panel's NoMotion, then SceneError unless the panel (and the
  // `other` panel a measure compares it with) has keyframes.
  void need_keyframes(std::size_t panel, const scene::MeasureName& measure, const std::string& pointer,
                      std::optional<std::size_t> other = std::nullopt) const;

  const motion::Stage* stage_;
  std::vector<std::optional<MotionMeasures>> measures_;
  std::vector<std::optional<FrameSteps>> steps_;
};

// Every claim of the stage's scene, in order. Throws as Measurer::value.
std::vector<ClaimOutcome> check_claims(const motion::Stage& stage);

// What the claims cost, in frames of a plain method (motion::frame_cost):
// the measures of each panel a claim names (what `pita check` budgets).
double claims_cost(const scene::Scene& scene);

}  // namespace pita::analysis
