// The animation's clock (docs/reference/animate.md "Animation"): how many frames, at which
// times, from the scene's "animation" and the command line's flags.
//
// Frame k (0-based) of N is at
//   t_k = first + (last - first) k / (N - 1)   (not looping: both ends shown), or
//   t_k = first + (last - first) k / N         (looping: the frame after the
//                                               last is the first again),
// where [first, last] is [t_0, t_n], the first and last knots of the scene's
// panels ("what": "motion"), or [0, 1], the parameter tau of the moving
// keyframes ("what": "pattern", PITA Sec. 7.4; docs/paper-notes.md N35). Times are scene times: the
// scene's "timing" (eases, arc length) shapes how the motion runs through them;
// for "pattern" its ease maps t to the keyframes' tau.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/ease.hpp"
#include "scene/scene.hpp"

namespace pita::animate {

// A bad animation request (exit 2): a flag or a field of "animation" out of
// range, or an output pita cannot make. what() names the flag or the pointer.
class AnimationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Flags of `pita animate` that override the scene's "animation".
struct Overrides {
  std::optional<double> fps;
  std::optional<double> duration;
  std::optional<int> frames;
};

struct Timeline {
  scene::Animation::What what = scene::Animation::What::motion;
  int frames = 2;     // N
  double fps = 30.0;  // frames per second of playback
  bool loop = true;
  int trail = 0;
  double first = 0.0;  // time of frame 0
  double last = 1.0;   // end of the time range
  // "pattern": the scene's timing ease, applied to the animation time t in
  // [0, 1] to give the keyframes' tau (linear without "timing").
  Ease tau_ease;

  // "pattern": tau = ease(t), the parameter of the moving keyframes at time t.
  double tau(double t) const { return ease(tau_ease, t); }

  // t_k (above); k in [0, N).
  double time(int k) const;
  // The time between two frames.
  double step() const;
  // How long the animation plays: N / fps seconds.
  double seconds() const { return frames / fps; }
  // The trail behind frame time t: up to `trail` earlier frame times, at
  // least `first`, oldest first.
  std::vector<double> trail_times(double t) const;
};

// The scene's timeline with the flags applied. With --frames and --duration
// but no --fps, fps = frames / duration; otherwise N = round(duration x fps)
// unless frames are given. Throws AnimationError naming the flag (--fps,
// --duration, --frames) or the scene's field.
Timeline make_timeline(const scene::Scene& scene, const Overrides& overrides = {});

// "motion" or "pattern".
std::string what_name(scene::Animation::What what);

}  // namespace pita::animate
