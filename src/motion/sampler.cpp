#include "motion/sampler.hpp"

#include <cmath>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "core/chains/chain.hpp"
#include "scene/limits.hpp"
#include "core/overloaded.hpp"

namespace pita::motion {

std::vector<double> uniform_times(double first, double last, int count) {
  if (count < 2) throw std::invalid_argument("uniform_times needs at least 2 samples");
  std::vector<double> times(static_cast<std::size_t>(count));
  const double span = last - first;
  const double intervals = static_cast<double>(count - 1);
  for (int i = 0; i < count; ++i) {
    times[static_cast<std::size_t>(i)] = first + span * static_cast<double>(i) / intervals;
  }
  times.back() = last;  // first + (last - first) may differ from last by an ulp
  return times;
}

std::vector<double> uniform_times(const SceneMotion& motion, int count) {
  std::vector<double> times = uniform_times(motion.first(), motion.last(), count);
  for (double t : times) {
    if (!std::isfinite(t)) {
      throw NoMotion(motion.file(), "", "the knots are too far apart to sample between them");
    }
  }
  return times;
}

std::vector<Frame> sample_arrows(const SceneMotion& motion, std::span<const double> times) {
  std::vector<Frame> frames;
  frames.reserve(times.size());
  for (double t : times) frames.push_back({t, motion.arrow_at(t)});
  return frames;
}

std::vector<PoseFrame> sample_poses(const SceneMotion& motion, std::span<const double> times) {
  std::vector<PoseFrame> frames;
  frames.reserve(times.size());
  for (double t : times) frames.push_back({t, motion.pose_at(t)});
  return frames;
}

std::vector<scene::PoseFrame3> sample_poses3(const SceneMotion& motion, std::span<const double> times) {
  std::vector<scene::PoseFrame3> frames;
  frames.reserve(times.size());
  for (double t : times) frames.push_back({t, motion.pose3_at(t)});
  return frames;
}

std::string frames_text(const scene::Panel& panel, const SceneMotion& motion, std::span<const double> times,
                        FramesFormat format) {
  const bool csv = format == FramesFormat::csv;
  const std::string chain = motion.chain() ? std::string(info(*motion.chain()).name) : "";
  return std::visit(
      overloaded{[&](const ArrowTrack&) {
                   const std::vector<Frame> frames = sample_arrows(motion, times);
                   return csv ? scene::frames_to_csv(frames) : scene::frames_to_json(scene::method_id(panel.keys), frames, chain);
                 },
                 [&](const PointTrack&) {
                   std::vector<scene::PointFrame> frames;
                   frames.reserve(times.size());
                   for (const double t : times) frames.push_back({t, motion.point_at(t)});
                   return csv ? scene::point_frames_to_csv(frames)
                              : scene::point_frames_to_json(scene::method_id(panel.keys), frames, chain);
                 },
                 [&](const PlanePoses&) {
                   const std::vector<PoseFrame> frames = sample_poses(motion, times);
                   return csv ? scene::pose_frames_to_csv(frames) : scene::pose_frames_to_json(scene::method_id(panel.keys), frames);
                 },
                 [&](const SpacePoses&) {
                   const std::vector<scene::PoseFrame3> frames = sample_poses3(motion, times);
                   return csv ? scene::pose_frames_to_csv(frames) : scene::pose_frames_to_json(scene::method_id(panel.keys), frames);
                 }},
      motion.built());
}

double check_eval_work(const scene::Scene& scene, const scene::Panel& panel, const SceneMotion& motion,
                       std::size_t frames, std::string_view advice) {
  const double work = static_cast<double>(frames) * frame_cost(panel);
  if (work > scene::kMaxEvalWork) {
    const scene::TrackMethod* track = scene::track_method(scene.keys);
    throw scene::SceneError(scene.path, track != nullptr && track->chain.has_value() ? "/chain" : "/keyframes",
                            fmt::format("{} frames of the {} cost about {:.3g} frames of the method, above the "
                                        "limit of {:.0g}: {}, or use the local \"blend\" chain",
                                        frames, motion.label(), work, scene::kMaxEvalWork, advice));
  }
  return work;
}

}  // namespace pita::motion
