// The numbers claims compare (scene/claim.hpp; docs/reference/check.md
// "Claims"), measured on the motions the stage built: `pita check`'s claims
// (claims.hpp) and the lint's small-feature check read them here.
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

// Where a claim's number comes from: pita measure's measures of the panel
// (measure_panel, kept once per panel), the frames its pattern draws, a
// comparison with another motion, or a property of Sec. 4. What value()
// computes and what claims_cost counts, from one list.
enum class Source { measures, frame_steps, comparison, property };
Source source_of(scene::MeasureKind kind);

// "panel 3 (P8 Lo-Pe)", "the scene (P6)": how outcomes name a panel, by its
// title or else its method.
std::string panel_name(const motion::Stage& stage, std::size_t index);

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

}  // namespace pita::analysis
