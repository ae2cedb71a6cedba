// How the frames a pattern draws change from one to the next (docs/reference/check.md
// "Claims"): what a reader sees as a jump in size, a flip of direction, or a
// frame shrinking or growing past the keyframes (PITA Fig. 19, Fig. 24).
//   - scale step: max_k |ln(m_{k+1} / m_k)| between consecutive frames;
//   - turn step: max_k |arg(v_{k+1} / v_k)|, in [0, pi], between consecutive
//     frame vectors v = q - p (a flip is pi; a step of more than pi reads as
//     its complement, as on the page);
//   - turn step time: the scene time half-way through that largest turn step;
//   - scale min / max: min_t m(t) / min_k m_k and max_t m(t) / max_k m_k over
//     dense samples (below 1: the motion shrinks past every keyframe; above
//     1: it grows past every keyframe).
#pragma once

#include <cstddef>
#include <optional>

#include "motion/stage.hpp"
#include "scene/measure_name.hpp"

namespace pita::analysis {

// Dense samples of scale min and max.
inline constexpr int kScaleSamples = 513;

struct FrameSteps {
  double scale_step = 0.0;
  double turn_step = 0.0;
  double scale_min = 1.0;
  double scale_max = 1.0;
  // The scene time half-way through the largest turn step (the first of
  // equal ones): "P2 turns fastest towards the end" (Fig. 24).
  double turn_step_time = 0.0;
};

// For the stage's panel `index` (keyframes): steps between its `samples`
// pattern frames (Panel::samples, evenly spaced in scene time over the
// knots, as the "pattern" layer draws them). Throws motion::NoMotion.
FrameSteps frame_steps(const motion::Stage& stage, std::size_t index);

// The number of `steps` that measure `kind` names ("scale-step", ...);
// nullopt for a measure that is not one of these five.
std::optional<double> frame_step(const FrameSteps& steps, scene::MeasureKind kind);
// Whether `kind` is one of the five.
inline bool is_frame_step(scene::MeasureKind kind) { return frame_step(FrameSteps{}, kind).has_value(); }

}  // namespace pita::analysis
