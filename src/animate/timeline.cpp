#include "animate/timeline.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/overloaded.hpp"
#include "scene/limits.hpp"

namespace pita::animate {

double Timeline::time(int k) const {
  if (loop) return first + (last - first) * static_cast<double>(k) / frames;
  if (k == frames - 1) return last;  // exactly the last knot
  return first + (last - first) * static_cast<double>(k) / (frames - 1);
}

double Timeline::step() const { return (last - first) / (loop ? frames : frames - 1); }

std::vector<double> Timeline::trail_times(double t) const {
  std::vector<double> times;
  const double dt = step();
  for (int j = trail; j >= 1; --j) {
    const double earlier = t - j * dt;
    if (earlier >= first - 1e-12 * std::max(1.0, std::abs(first))) times.push_back(std::max(earlier, first));
  }
  return times;
}

std::string what_name(scene::Animation::What what) {
  return what == scene::Animation::What::pattern ? "pattern" : "motion";
}

Timeline make_timeline(const scene::Scene& scene, const Overrides& overrides) {
  const scene::Animation& animation = scene.animation;
  if (overrides.fps && !(*overrides.fps > 0.0 && *overrides.fps <= scene::kMaxFps)) {
    throw AnimationError(
        fmt::format("--fps: frames per second must be in (0, {:g}] (got {:g})", scene::kMaxFps, *overrides.fps));
  }
  if (overrides.duration && !(*overrides.duration > 0.0 && *overrides.duration <= scene::kMaxAnimationDuration)) {
    throw AnimationError(fmt::format("--duration: seconds must be in (0, {:g}] (got {:g})",
                                     scene::kMaxAnimationDuration, *overrides.duration));
  }
  if (overrides.frames &&
      (*overrides.frames < scene::kMinAnimationFrames || *overrides.frames > scene::kMaxAnimationFrames)) {
    throw AnimationError(fmt::format("--frames: an animation has {} to {} frames (got {})", scene::kMinAnimationFrames,
                                     scene::kMaxAnimationFrames, *overrides.frames));
  }
  Timeline timeline;
  timeline.what = animation.what;
  timeline.loop = animation.loop;
  timeline.trail = animation.trail;
  const double duration = overrides.duration.value_or(animation.duration);
  if (overrides.frames) {
    timeline.frames = *overrides.frames;
    timeline.fps = overrides.fps        ? *overrides.fps
                   : overrides.duration ? *overrides.frames / *overrides.duration
                                        : animation.fps;
  } else {
    timeline.fps = overrides.fps.value_or(animation.fps);
    if (animation.frames && !overrides.fps && !overrides.duration) {
      timeline.frames = *animation.frames;
    } else {
      const double count = std::round(duration * timeline.fps);
      if (!(count >= scene::kMinAnimationFrames && count <= scene::kMaxAnimationFrames)) {
        throw AnimationError(
            fmt::format("{}: {:g} s at {:g} frames per second gives {:g} frames; an animation has "
                        "{} to {} frames",
                        overrides.duration ? "--duration"
                        : overrides.fps    ? "--fps"
                                           : scene.path + ": /animation",
                        duration, timeline.fps, count, scene::kMinAnimationFrames, scene::kMaxAnimationFrames));
      }
      timeline.frames = static_cast<int>(count);
    }
  }
  if (!(timeline.seconds() <= scene::kMaxAnimationDuration)) {
    throw AnimationError(
        fmt::format("{}: {} frames at {:g} frames per second play {:g} s; an animation plays at most "
                    "{:g} s",
                    overrides.fps ? "--fps" : scene.path + ": /animation/fps", timeline.frames, timeline.fps,
                    timeline.seconds(), scene::kMaxAnimationDuration));
  }
  if (!(timeline.fps > 0.0 && timeline.fps <= scene::kMaxFps)) {
    throw AnimationError(
        fmt::format("--frames / --duration: {} frames in {:g} s is {:g} frames per second; at most {:g}",
                    timeline.frames, duration, timeline.fps, scene::kMaxFps));
  }
  if (timeline.what == scene::Animation::What::pattern) {
    timeline.first = 0.0;
    timeline.last = 1.0;
    timeline.tau_ease = scene.timing.ease;
  } else {
    bool any = false;
    for (const scene::Panel& panel : scene.panels) {
      const std::vector<double> knots = scene::knots(panel.keys);
      if (knots.empty()) continue;
      timeline.first = any ? std::min(timeline.first, knots.front()) : knots.front();
      timeline.last = any ? std::max(timeline.last, knots.back()) : knots.back();
      any = true;
    }
    if (!any) throw AnimationError(scene.path + ": nothing moves: the scene has no keyframes or poses to animate");
  }
  return timeline;
}

}  // namespace pita::animate
