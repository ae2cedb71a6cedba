#include "analysis/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <variant>
#include <vector>

#include "analysis/arrow_distance.hpp"
#include "core/carrier.hpp"
#include "core/discrepancy.hpp"
#include "core/methods.hpp"
#include "core/overloaded.hpp"
#include "core/pose_traits.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"

namespace pita::analysis {

double largest_keyframe_magnitude(const scene::Panel& panel) {
  double largest = 0.0;
  for (const Keyframe& k : std::get<scene::KeyframeKeys>(panel.keys).keyframes) largest = std::max(largest, k.arrow.m);
  return largest;
}

double vector_angle(const motion::Stage& stage, std::size_t index, Method other, double t) {
  const scene::Panel& panel = stage.panel(index);
  const Arrow mine = stage.motion(index).arrow_at(t);  // NoMotion unless the panel has keyframes
  const Arrow theirs = motion::with_method(stage.scene(), panel, other).arrow_at(t);
  const double floor = kAngleVectorFloor * largest_keyframe_magnitude(panel);
  if (!(std::abs(mine.vector()) > floor) || !(std::abs(theirs.vector()) > floor)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return std::arg(theirs.vector() / mine.vector());
}

double handle_shift(const motion::Stage& stage, std::size_t index) {
  const scene::Panel& panel = stage.panel(index);
  const motion::SceneMotion& own = stage.motion(index);
  (void)own.arrows();  // NoMotion unless the panel has keyframes
  scene::Panel reference;
  const motion::SceneMotion base = motion::with_scene_keyframes(stage.scene(), panel, &reference);
  (void)base.arrows();  // the same for the scene's
  const scene::KeyframeKeys& mine = std::get<scene::KeyframeKeys>(panel.keys);
  const scene::KeyframeKeys& theirs = std::get<scene::KeyframeKeys>(reference.keys);
  const auto by_knot = [](const Keyframe& a, const Keyframe& b) { return a.t < b.t; };
  const auto [own_first, own_last] = std::minmax_element(mine.keyframes.begin(), mine.keyframes.end(), by_knot);
  const auto [base_first, base_last] = std::minmax_element(theirs.keyframes.begin(), theirs.keyframes.end(), by_knot);
  const double first = std::max(own_first->t, base_first->t);
  const double last = std::min(own_last->t, base_last->t);
  double shift = 0.0;
  for (const double t : motion::uniform_times(first, last, kHandleShiftSamples)) {
    const Affine2 S = carrier(mine.handle(), own.arrow_at(t));
    const Affine2 S0 = carrier(theirs.handle(), base.arrow_at(t));
    for (const scene::ShapeOutline& shape : scene::figure_of(panel, mine).shapes) {
      for (const Point x : shape.points) shift = std::max(shift, std::abs(apply(S, x) - apply(S0, x)));
    }
  }
  return shift;
}

double panel_angle(const motion::Stage& stage, std::size_t index, std::size_t other, double t) {
  const Arrow mine = stage.motion(index).arrow_at(t);  // NoMotion unless the panel has keyframes
  const Arrow theirs = stage.motion(other).arrow_at(t);
  const double floor = kAngleVectorFloor * std::max(largest_keyframe_magnitude(stage.panel(index)),
                                                    largest_keyframe_magnitude(stage.panel(other)));
  if (!(std::abs(mine.vector()) > floor) || !(std::abs(theirs.vector()) > floor)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return std::arg(theirs.vector() / mine.vector());
}

namespace {

// The times both panels' knots cover (an empty list when they share none).
std::vector<double> common_times(const motion::SceneMotion& mine, const motion::SceneMotion& theirs) {
  const double first = std::max(mine.first(), theirs.first());
  const double last = std::min(mine.last(), theirs.last());
  if (!(first < last)) return {};
  return motion::uniform_times(first, last, kFrameDistanceSamples);
}

// The times a frame-distance compares: `at` alone, or those both panels share.
std::vector<double> compared_times(const motion::SceneMotion& mine, const motion::SceneMotion& theirs,
                                   std::optional<double> at) {
  if (at) return {*at};
  return common_times(mine, theirs);
}

double arrow_distance(const motion::SceneMotion& mine, const motion::SceneMotion& theirs, std::optional<double> at) {
  (void)mine.arrows();  // NoMotion unless both panels have keyframes
  (void)theirs.arrows();
  const std::vector<double> times = compared_times(mine, theirs, at);
  if (times.empty()) return std::numeric_limits<double>::quiet_NaN();  // no common time
  double distance = 0.0;
  for (const double t : times) {
    const Arrow a = mine.arrow_at(t);
    const Arrow b = theirs.arrow_at(t);
    distance = std::max({distance, std::abs(a.p - b.p), std::abs(a.q() - b.q())});
  }
  return distance;
}

double gap(Point x, Point y) { return std::abs(x - y); }
double gap(const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return (x - y).norm(); }

// Poses: the corners of the reference simplex (the triangle, the
// tetrahedron) carried by both motions, as an arrow's p and q are.
template <class Pose>
double pose_distance(const motion::SceneMotion& mine, const motion::SceneMotion& theirs,
                     const typename PoseTraits<Pose>::Simplex& corners, std::optional<double> at) {
  const std::vector<double> times = compared_times(mine, theirs, at);
  if (times.empty()) return std::numeric_limits<double>::quiet_NaN();
  double distance = 0.0;
  for (const double t : times) {
    const Pose a = mine.pose_at<Pose>(t);
    const Pose b = theirs.pose_at<Pose>(t);
    for (const auto& corner : corners) distance = std::max(distance, gap(apply(a, corner), apply(b, corner)));
  }
  return distance;
}

// The keyframe of the smallest knot of a panel of keyframes.
const Keyframe& first_keyframe(const scene::Panel& panel) {
  const std::vector<Keyframe>& keys = std::get<scene::KeyframeKeys>(panel.keys).keyframes;
  return *std::min_element(keys.begin(), keys.end(), [](const Keyframe& a, const Keyframe& b) { return a.t < b.t; });
}

}  // namespace

double carried_distance(const motion::Stage& stage, std::size_t index, std::size_t other) {
  const motion::SceneMotion& mine = stage.motion(index);
  const motion::SceneMotion& theirs = stage.motion(other);
  (void)mine.arrows();  // NoMotion unless both panels have keyframes
  (void)theirs.arrows();
  const Affine2 S = carrier(first_keyframe(stage.panel(other)).arrow, first_keyframe(stage.panel(index)).arrow);
  const std::vector<double> times = common_times(mine, theirs);
  if (times.empty()) return std::numeric_limits<double>::quiet_NaN();
  double distance = 0.0;
  for (const double t : times) {
    const Arrow a = mine.arrow_at(t);
    const Arrow b = theirs.arrow_at(t);
    distance = std::max({distance, std::abs(a.p - apply(S, b.p)), std::abs(a.q() - apply(S, b.q()))});
  }
  return distance;
}

namespace {

// How far two motions of the stage's panel `index`'s kind are apart: at
// `at` alone, or over the knots both cover.
double motions_distance(const motion::Stage& stage, std::size_t index, const motion::SceneMotion& mine,
                        const motion::SceneMotion& theirs, std::optional<double> at) {
  // A scene's panels are all of its family: keyframes or points, or poses of
  // one dimension.
  const auto arrows = [&] { return arrow_distance(mine, theirs, at); };  // NoMotion for points
  const scene::Scene& scene = stage.scene();
  return std::visit(
      overloaded{
          [&](const scene::KeyframeKeys&) { return arrows(); }, [&](const scene::PointKeys&) { return arrows(); },
          [&](const scene::PlanePoseKeys&) {
            return pose_distance<Affine2>(mine, theirs, scene::figure_of<scene::PlanePoseKeys>(scene).reference, at);
          },
          [&](const scene::SpacePoseKeys&) {
            return pose_distance<Affine3>(mine, theirs, scene::figure_of<scene::SpacePoseKeys>(scene).reference, at);
          }},
      stage.panel(index).keys);
}

}  // namespace

double frame_distance(const motion::Stage& stage, std::size_t index, std::size_t other, std::optional<double> at) {
  return motions_distance(stage, index, stage.motion(index), stage.motion(other), at);
}

double method_distance(const motion::Stage& stage, std::size_t index, const AnyMethod& method) {
  const motion::SceneMotion& mine = stage.motion(index);
  const motion::SceneMotion theirs = motion::with_method(stage.scene(), stage.panel(index), method);
  return motions_distance(stage, index, mine, theirs, std::nullopt);
}

double frame_distance(const motion::SceneMotion& mine, const motion::SceneMotion& theirs) {
  return arrow_distance(mine, theirs, std::nullopt);
}

double knot_distance(const motion::Stage& stage, std::size_t index) {
  const motion::SceneMotion& motion = stage.motion(index);
  (void)motion.arrows();  // NoMotion unless the panel has keyframes
  double distance = 0.0;
  for (const Keyframe& k : std::get<scene::KeyframeKeys>(stage.panel(index).keys).keyframes) {
    distance = std::max(distance, endpoint_distance(k.arrow, motion.arrow_at(k.t)));
  }
  return distance;
}

double guess_gap(const motion::Stage& stage, std::size_t index, const scene::Guess& guess, bool discrepancy) {
  const Arrow frame = stage.motion(index).arrow_at(guess.t);
  return discrepancy ? pita::discrepancy(guess.arrow, frame) : endpoint_distance(guess.arrow, frame);
}

}  // namespace pita::analysis
