// The one sampler: the times at which motions are evaluated, and the frames
// of a SceneMotion at those times. eval, render, golden and analysis all
// sample through here.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/affine2.hpp"
#include "core/arrow.hpp"
#include "motion/scene_motion.hpp"
#include "scene/frames.hpp"
#include "scene/scene.hpp"

namespace pita::motion {

// `count` >= 2 evenly spaced times from `first` to `last`, both included:
// t_i = first + (last - first) i / (count - 1). The ends are exactly `first`
// and `last` (so the keyframes themselves are reproduced at the ends). Throws
// std::invalid_argument if count < 2.
std::vector<double> uniform_times(double first, double last, int count);

// The i-th of those times alone (uniform_times(first, last, count)[i]).
double uniform_time(double first, double last, int count, int i);

// `count` evenly spaced scene times over the motion's knots [t_0, t_n].
// Throws NoMotion when the knots are too far apart to sample between them.
std::vector<double> uniform_times(const SceneMotion& motion, int count);

// The arrow D(t), or the pose A(t), of a motion at scene time t (the types
// the frame writers of scene/frames.hpp print).
using Frame = scene::Frame;
template <class Pose>
using PoseFrame = scene::PoseFrame<Pose>;

// The frames at `times` (scene times, any order; outside the knots they
// extrapolate): arrows, or poses of the plane (Pose = Affine2) or of space
// (Affine3). Throw NoMotion as SceneMotion does.
std::vector<Frame> sample_arrows(const SceneMotion& motion, std::span<const double> times);
template <class Pose>
std::vector<PoseFrame<Pose>> sample_poses(const SceneMotion& motion, std::span<const double> times);

// Frames of `motion` (the motion of `panel` in `scene`) cost `frames` times
// its frame cost; above scene::kMaxEvalWork this throws scene::SceneError at
// the pointer that makes them dear (/chain, else /keyframes), with `advice`
// (what the command's user can change: "ask for fewer frames (--samples)").
// Returns the work. What `pita eval` and the frames of `pita sweep` check.
double check_eval_work(const scene::Scene& scene, const scene::Panel& panel, const SceneMotion& motion,
                       std::size_t frames, std::string_view advice);

using FramesFormat = scene::FramesFormat;

// The times at which frames are printed: those given, or `count` evenly
// spaced ones over a motion's knots, each computed when asked for, so that a
// million frames need no million-entry vector.
class FrameTimes {
 public:
  explicit FrameTimes(std::span<const double> given) : given_(given), count_(given.size()) {}
  // uniform_times(motion, count), one at a time: at() throws NoMotion where
  // that throws (the knots too far apart to sample between them).
  FrameTimes(const SceneMotion& motion, int count);

  std::size_t size() const { return count_; }
  double at(std::size_t i) const;

 private:
  std::span<const double> given_;
  const SceneMotion* motion_ = nullptr;  // set for uniform times
  std::size_t count_ = 0;
};

// Where streamed text goes, and whether what it received can be taken back.
struct TextSink {
  std::function<void(std::string_view)> write;
  // false for standard output: frames_text then evaluates every frame once
  // before writing any, so that a frame that is not finite leaves nothing
  // written. true for a string or a temporary file, dropped on an exception.
  bool discards_on_throw = true;
};

// Bytes the writers gather before handing them to a sink.
inline constexpr std::size_t kFramesChunkBytes = std::size_t{1} << 16;

// What `pita eval` prints for `motion` (the motion of `panel`) at `times`:
// arrows, timed points or poses, as JSON or CSV (scene/frames.hpp), handed to
// `sink` in chunks of about kFramesChunkBytes, in memory that does not grow
// with the number of frames. Throws NoMotion as SceneMotion does and
// std::invalid_argument for a frame that is not finite; exceptions of
// sink.write pass through.
void write_frames(const scene::Panel& panel, const SceneMotion& motion, const FrameTimes& times, FramesFormat format,
                  const TextSink& sink);

// What `pita eval` prints for a scene without a motion (scene::has_motion_keys:
// a pose scene without poses): no frames, in the format and with the columns
// of its kind (poses of the plane or of space).
std::string no_frames_text(const scene::Scene& scene, FramesFormat format);

// The same text as one string.
std::string frames_text(const scene::Panel& panel, const SceneMotion& motion, std::span<const double> times,
                        FramesFormat format);

}  // namespace pita::motion
