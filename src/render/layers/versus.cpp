// "versus" (SAM Figs. 4, 5): the shapes under another method's motion through
// the panel's poses, each pose raised to `power` as a displacement from the
// first pose (scene/layers.hpp, VersusLayer).
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/pose_method.hpp"
#include "motion/no_motion.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "render/carried_shapes.hpp"
#include "render/layer_cost.hpp"
#include "render/layers/pose_layers.hpp"

namespace pita::render {

namespace {

std::string versus_count_reason(PoseMethod method, std::size_t count) {
  const PoseMethodInfo& about = info(method);
  const std::string wanted = about.min_poses == about.max_poses ? fmt::format("exactly {}", about.min_poses)
                                                                : fmt::format("at least {}", about.min_poses);
  return fmt::format("method {} takes {} poses (the panel has {})", about.id, wanted, count);
}

}  // namespace

void draw_pose_layer(PosePanel<Affine2>& panel, const scene::VersusLayer& layer) {
  const PoseMethodInfo& about = info(layer.method);
  const std::vector<TimedPose>& poses = panel.keys().poses;
  const auto count = static_cast<int>(poses.size());
  if (count < about.min_poses || count > about.max_poses) panel.fail(versus_count_reason(layer.method, poses.size()));
  std::optional<motion::SceneMotion> motion;
  try {
    motion.emplace(motion::with_method(panel.scene(), panel.panel(), layer.method));
  } catch (const motion::NoMotion& error) {
    panel.fail(fmt::format("method {}: {}", about.id, error.reason()));
  }
  const FrameSelection* selection = panel.selection();
  std::vector<double> ts = layer.at;
  if (selection != nullptr) {
    ts = selection->trail;
    ts.push_back(selection->t);
  } else if (ts.empty()) {
    const double from = layer.range ? layer.range->from : motion->first();
    const double to = layer.range ? layer.range->to : motion->last();
    ts = motion::uniform_times(from, to, layer.samples.value_or(panel.panel().samples));
  }
  const scene::ShapesLayer style{layer.line, layer.fill, layer.fill_opacity, std::nullopt, std::nullopt, {}, false};
  const Affine2 first = poses.front().pose;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    Affine2 pose;
    try {
      pose = motion->pose_at<Affine2>(ts[i]);
    } catch (const motion::NoMotion& error) {
      panel.fail(fmt::format("method {}: {}", about.id, error.reason()));
    }
    // (D(t) o D(t0)^-1)^k o D(t0), by k - 1 compositions.
    const Affine2 step = compose(pose, inverse(first));
    for (int k = 1; k < layer.power; ++k) pose = compose(step, pose);
    // The power multiplies the step: a large one can overflow where the
    // pose itself did not (no NaN reaches a figure).
    if (!pose.L.allFinite() || !pose.b.allFinite()) {
      panel.fail(
          fmt::format("method {}: the pose at t = {} to the power {} is not finite (it overflows); use a "
                      "smaller \"power\" or times nearer the first pose",
                      about.id, ts[i], layer.power));
    }
    const double fade = selection != nullptr ? trail_fade(i, ts.size()) : 1.0;
    for (Shape& shape : carried_shapes(panel.shapes(), pose, style, panel.scene().canvas.y_up, fade)) {
      panel.push(static_cast<int>(i), std::move(shape), selection != nullptr);
    }
  }
}

// Its cost (render/layer_cost.hpp).
namespace detail {

void LayerCost::operator()(const scene::VersusLayer& l) {
  if (!l.at.empty()) {
    add(layer_ + "/at", fmt::format("{} frames of compared shapes", l.at.size()),
        static_cast<double>(l.at.size()) * (shapes_units() + l.power));
    return;
  }
  frames(l.samples, "compared shapes", shapes_units() + l.power);
}

}  // namespace detail

}  // namespace pita::render
