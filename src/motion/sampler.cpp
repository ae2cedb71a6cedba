#include "motion/sampler.hpp"

#include <cmath>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "core/chains/chain.hpp"
#include "core/overloaded.hpp"
#include "scene/limits.hpp"

namespace pita::motion {

double uniform_time(double first, double last, int count, int i) {
  if (count < 2) throw std::invalid_argument("uniform_times needs at least 2 samples");
  // first + (last - first) may differ from last by an ulp
  if (i == count - 1) return last;
  return first + (last - first) * static_cast<double>(i) / static_cast<double>(count - 1);
}

std::vector<double> uniform_times(double first, double last, int count) {
  if (count < 2) throw std::invalid_argument("uniform_times needs at least 2 samples");
  std::vector<double> times(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) times[static_cast<std::size_t>(i)] = uniform_time(first, last, count, i);
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

template <class Pose>
std::vector<PoseFrame<Pose>> sample_poses(const SceneMotion& motion, std::span<const double> times) {
  std::vector<PoseFrame<Pose>> frames;
  frames.reserve(times.size());
  for (double t : times) frames.push_back({t, motion.pose_at<Pose>(t)});
  return frames;
}
template std::vector<PoseFrame<Affine2>> sample_poses(const SceneMotion&, std::span<const double>);
template std::vector<PoseFrame<Affine3>> sample_poses(const SceneMotion&, std::span<const double>);

FrameTimes::FrameTimes(const SceneMotion& motion, int count)
    : motion_(&motion), count_(count < 2 ? 0 : static_cast<std::size_t>(count)) {
  if (count < 2) throw std::invalid_argument("uniform_times needs at least 2 samples");
}

double FrameTimes::at(std::size_t i) const {
  if (motion_ == nullptr) return given_[i];
  const double t = uniform_time(motion_->first(), motion_->last(), static_cast<int>(count_), static_cast<int>(i));
  if (!std::isfinite(t)) throw NoMotion(motion_->file(), "", "the knots are too far apart to sample between them");
  return t;
}

namespace {

// The frame of `motion` at t, of the kind `Track` stands for (the printer's row).
Frame frame_at(const ArrowTrack&, const SceneMotion& motion, double t) { return {t, motion.arrow_at(t)}; }
scene::PointFrame frame_at(const PointTrack&, const SceneMotion& motion, double t) { return {t, motion.point_at(t)}; }
template <class Pose>
PoseFrame<Pose> frame_at(const PoseTrack<Pose>&, const SceneMotion& motion, double t) {
  return {t, motion.pose_at<Pose>(t)};
}

}  // namespace

void write_frames(const scene::Panel& panel, const SceneMotion& motion, const FrameTimes& times, FramesFormat format,
                  const TextSink& sink) {
  const std::string chain = motion.chain() ? std::string(info(*motion.chain()).name) : "";
  std::visit(
      [&](const auto& track) {
        using Row = decltype(frame_at(track, motion, 0.0));
        scene::FramesPrinter<Row> printer(format, scene::method_id(panel.keys), chain);
        scene::FramesBuffer chunk;
        if (!sink.discards_on_throw) {
          // Every frame once, checked as row() checks it, so that a frame
          // that is not finite throws before any byte reaches a sink that
          // cannot take it back.
          for (std::size_t i = 0; i < times.size(); ++i) {
            scene::FramesPrinter<Row>::require_finite(frame_at(track, motion, times.at(i)));
          }
        }
        chunk.reserve(kFramesChunkBytes + 1024);
        const auto flush = [&] {
          sink.write(std::string_view(chunk.data(), chunk.size()));
          chunk.clear();
        };
        printer.head(chunk);
        for (std::size_t i = 0; i < times.size(); ++i) {
          printer.row(chunk, frame_at(track, motion, times.at(i)));
          if (chunk.size() >= kFramesChunkBytes) flush();
        }
        printer.tail(chunk);
        flush();
      },
      motion.built());
}

std::string frames_text(const scene::Panel& panel, const SceneMotion& motion, std::span<const double> times,
                        FramesFormat format) {
  std::string text;
  write_frames(panel, motion, FrameTimes(times), format, TextSink{[&](std::string_view bytes) { text += bytes; }});
  return text;
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

std::string no_frames_text(const scene::Scene& scene, FramesFormat format) {
  const std::string method = scene::method_id(scene.keys);
  const auto none = [&](auto row) {
    using Row = decltype(row);
    scene::FramesPrinter<Row> printer(format, method);
    scene::FramesBuffer text;
    printer.head(text);
    printer.tail(text);
    return fmt::to_string(text);
  };
  // Only a pose scene may have no motion (scene::has_motion_keys); any kind
  // prints its own empty document.
  return std::visit(overloaded{[&](const scene::KeyframeKeys&) { return none(scene::Frame{}); },
                               [&](const scene::PointKeys&) { return none(scene::PointFrame{}); },
                               [&](const scene::PlanePoseKeys&) { return none(PoseFrame<Affine2>{}); },
                               [&](const scene::SpacePoseKeys&) { return none(PoseFrame<Affine3>{}); }},
                    scene.keys);
}

}  // namespace pita::motion
