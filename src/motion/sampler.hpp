// The one sampler: the times at which motions are evaluated, and the frames
// of a SceneMotion at those times. eval, render, golden and analysis all
// sample through here.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/affine2.hpp"
#include "core/arrow.hpp"
#include "motion/scene_motion.hpp"
#include "scene/frames.hpp"

namespace pita::motion {

// `count` >= 2 evenly spaced times from `first` to `last`, both included:
// t_i = first + (last - first) i / (count - 1). The ends are exactly `first`
// and `last` (so the keyframes themselves are reproduced at the ends). Throws
// std::invalid_argument if count < 2.
std::vector<double> uniform_times(double first, double last, int count);

// `count` evenly spaced scene times over the motion's knots [t_0, t_n].
// Throws NoMotion when the knots are too far apart to sample between them.
std::vector<double> uniform_times(const SceneMotion& motion, int count);

// The arrow D(t), or the pose A(t), of a motion at scene time t (the types
// the frame writers of scene/frames.hpp print).
using Frame = scene::Frame;
using PoseFrame = scene::PoseFrame;

// The frames at `times` (scene times, any order; outside the knots they
// extrapolate). Throw NoMotion as SceneMotion does.
std::vector<Frame> sample_arrows(const SceneMotion& motion, std::span<const double> times);
std::vector<PoseFrame> sample_poses(const SceneMotion& motion, std::span<const double> times);
std::vector<scene::PoseFrame3> sample_poses3(const SceneMotion& motion, std::span<const double> times);

// Frames of `motion` (the motion of `panel` in `scene`) cost `frames` times
// its frame cost; above scene::kMaxEvalWork this throws scene::SceneError at
// the pointer that makes them dear (/chain, else /keyframes), with `advice`
// (what the command's user can change: "ask for fewer frames (--samples)").
// Returns the work. What `pita eval` and the frames of `pita sweep` check.
double check_eval_work(const scene::Scene& scene, const scene::Panel& panel, const SceneMotion& motion,
                       std::size_t frames, std::string_view advice);

enum class FramesFormat { json, csv };

// What `pita eval` prints for `motion` (the motion of `panel`) at `times`:
// arrows, timed points or poses, as JSON or CSV (scene/frames.hpp). Throws
// NoMotion as SceneMotion does.
std::string frames_text(const scene::Panel& panel, const SceneMotion& motion, std::span<const double> times,
                        FramesFormat format);

}  // namespace pita::motion
