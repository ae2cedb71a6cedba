#include "analysis/frame_steps.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "analysis/comparison.hpp"
#include "motion/sampler.hpp"

namespace pita::analysis {

namespace {

double smallest_magnitude(const scene::Panel& panel) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const Keyframe& k : std::get<scene::KeyframeKeys>(panel.keys).keyframes)
    smallest = std::min(smallest, k.arrow.m);
  return smallest;
}

}  // namespace

FrameSteps frame_steps(const motion::Stage& stage, std::size_t index) {
  const motion::SceneMotion& motion = stage.motion(index);
  (void)motion.arrows();  // NoMotion unless the panel has keyframes
  const scene::Panel& panel = stage.panel(index);
  // A frame shorter than this has no size or direction to speak of: its
  // steps are measured from the floor (finite, and large).
  const double floor = kAngleVectorFloor * largest_keyframe_magnitude(panel);
  FrameSteps steps;
  const std::vector<double> times = motion::uniform_times(motion, panel.samples);
  steps.turn_step_time = times.front();
  const std::vector<motion::Frame> frames = motion::sample_arrows(motion, times);
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const Vector before = frames[k - 1].arrow.vector();
    const Vector after = frames[k].arrow.vector();
    const double m0 = std::max(std::abs(before), floor);
    const double m1 = std::max(std::abs(after), floor);
    steps.scale_step = std::max(steps.scale_step, std::abs(std::log(m1 / m0)));
    if (std::abs(before) > floor && std::abs(after) > floor) {
      const double turn = std::abs(std::arg(after / before));
      if (turn > steps.turn_step) {
        steps.turn_step = turn;
        steps.turn_step_time = (times[k - 1] + times[k]) / 2.0;
      }
    }
  }
  double low = std::numeric_limits<double>::infinity();
  double high = 0.0;
  const std::vector<double> dense = motion::uniform_times(motion, kScaleSamples);
  for (const motion::Frame& frame : motion::sample_arrows(motion, dense)) {
    const double m = std::abs(frame.arrow.vector());
    low = std::min(low, m);
    high = std::max(high, m);
  }
  steps.scale_min = low / smallest_magnitude(panel);
  steps.scale_max = high / largest_keyframe_magnitude(panel);
  return steps;
}

std::optional<double> frame_step(const FrameSteps& steps, scene::MeasureKind kind) {
  switch (kind) {
    case scene::MeasureKind::scale_step:
      return steps.scale_step;
    case scene::MeasureKind::turn_step:
      return steps.turn_step;
    case scene::MeasureKind::scale_min:
      return steps.scale_min;
    case scene::MeasureKind::scale_max:
      return steps.scale_max;
    case scene::MeasureKind::turn_step_time:
      return steps.turn_step_time;
    default:
      return std::nullopt;
  }
}

}  // namespace pita::analysis
