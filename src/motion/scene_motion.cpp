#include "motion/scene_motion.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "core/finite_difference.hpp"
#include "core/limits.hpp"
#include "core/methods.hpp"
#include "core/overloaded.hpp"
#include "core/pitas/registry.hpp"

namespace pita::motion {

namespace {

const char* point_name(scene::TrackedPoint point) {
  switch (point) {
    case scene::TrackedPoint::start:
      return "p";
    case scene::TrackedPoint::end:
      return "q";
    case scene::TrackedPoint::middle:
      return "mid";
  }
  return "p";
}

// The point of a frame arc length follows: for arrows p, q or their midpoint;
// for poses the images of the reference triangle's first two points, or of
// their midpoint (docs/reference/scene-format.md "Timing").
Point tracked(const Arrow& frame, scene::TrackedPoint point) {
  switch (point) {
    case scene::TrackedPoint::start:
      return frame.p;
    case scene::TrackedPoint::end:
      return frame.q();
    case scene::TrackedPoint::middle:
      return 0.5 * (frame.p + frame.q());
  }
  return frame.p;
}

}  // namespace

std::string method_label(const scene::Scene&, const scene::Panel& panel) {
  const auto track = [&](const scene::TrackMethod& given) {
    const MethodInfo& about = info(given.method);
    std::string label = about.mnemonic.empty() || about.mnemonic == about.id
                            ? std::string(about.id)
                            : fmt::format("{} ({})", about.id, about.mnemonic);
    if (const std::optional<Chain> chain = chain_of(panel)) label += fmt::format(", {} chain", info(*chain).name);
    return label;
  };
  // "SAM", "P6 (La-LP)": as the registry labels the pose method.
  const auto poses = [](const auto& given) { return pita::method_label(entry_of(given.method)); };
  return std::visit(overloaded{[&](const scene::KeyframeKeys& given) { return track(given); },
                               [&](const scene::PointKeys& given) { return track(given); },
                               [&](const scene::PlanePoseKeys& given) { return poses(given); },
                               [&](const scene::SpacePoseKeys& given) { return poses(given); }},
                    panel.keys);
}

namespace {

// The chain of a track of `length` keyframes: its own, else the method's
// default when the track is longer than the method takes.
std::optional<Chain> track_chain(const scene::TrackMethod& track, std::size_t length) {
  if (track.chain) return track.chain;
  if (length > static_cast<std::size_t>(info(track.method).keyframe_count)) return default_chain(track.method);
  return std::nullopt;
}

}  // namespace

std::optional<Chain> chain_of(const scene::Panel& panel) {
  return std::visit(
      overloaded{[](const scene::KeyframeKeys& given) { return track_chain(given, given.track_length()); },
                 // A curve through n points chains its n - 1 edge arrows.
                 [](const scene::PointKeys& given) { return track_chain(given, given.track_length()); },
                 [](const scene::PlanePoseKeys&) { return std::optional<Chain>(); },
                 [](const scene::SpacePoseKeys&) { return std::optional<Chain>(); }},
      panel.keys);
}

double frame_cost(const scene::Panel& panel) {
  const auto track = [&](std::size_t length) {
    const std::optional<Chain> chain = chain_of(panel);
    return chain ? chain_frame_cost(*chain, length) : 1.0;
  };
  return std::visit(
      overloaded{[&](const scene::KeyframeKeys& given) { return track(given.track_length()); },
                 // Two tracks per frame (PITA Eq. 48-50).
                 [&](const scene::PointKeys& given) { return 2.0 * track(given.track_length()); },
                 [](const scene::PlanePoseKeys&) { return 1.0; }, [](const scene::SpacePoseKeys&) { return 1.0; }},
      panel.keys);
}

PointCurveMotion point_curve(const scene::Scene& scene, const scene::Panel& panel, PointCurve curve) {
  const auto* given = std::get_if<scene::PointKeys>(&panel.keys);
  if (given == nullptr) {
    throw NoMotion(scene.path, panel.motion_pointer,
                   "a point-trajectory draws a curve through timed \"points\"; this panel has none");
  }
  const std::string label = method_label(scene, panel);
  const ArrowTrackFactory track = [given](std::span<const Keyframe> keys) {
    return make_motion(given->method, keys, given->options, given->chain);
  };
  try {
    return PointCurveMotion(curve, given->points, track);
  } catch (const MotionDomainError& error) {
    throw NoMotion(scene.path, panel.motion_pointer,
                   fmt::format("method {} has no motion through the edges of these points: {}", label, error.what()));
  } catch (const std::invalid_argument& error) {
    // The core's messages start with the curve's name; say it once.
    std::string_view reason = error.what();
    const std::string prefix = std::string(info(curve).name) + ": ";
    if (reason.starts_with(prefix)) reason.remove_prefix(prefix.size());
    throw NoMotion(scene.path, panel.motion_pointer,
                   fmt::format("the {} curve cannot pass through these points: {}", info(curve).name, reason));
  }
}

namespace {

// The motion through the poses, with the scene's reference simplex: the
// plane's motions also take the reference triangle (rARAP, ASAP and TSB move
// it, core/pose_motion.hpp).
PlanePoses make_pose_track(const scene::Scene& scene, const scene::PlanePoseKeys& keys) {
  const auto& reference = scene::figure_of(scene, keys).reference;
  return {std::make_shared<const PoseMotion>(keys.method, keys.poses, keys.subdivisions, reference), reference};
}
SpacePoses make_pose_track(const scene::Scene& scene, const scene::SpacePoseKeys& keys) {
  return {std::make_shared<const SamFamilyMotion<Affine3>>(keys.method, keys.poses, keys.subdivisions),
          scene::figure_of(scene, keys).reference};
}

// The motion of the panel's keyframes, points or poses, refused with NoMotion
// (at the panel's motion pointer) when the method has none through them.
template <class Pose>
auto build_poses(const scene::Scene& scene, const scene::Panel& panel, const scene::PoseKeys<Pose>& keys) {
  const auto refuse = [&](const std::string& reason) { return NoMotion(scene.path, panel.motion_pointer, reason); };
  if (keys.poses.empty()) throw refuse("the panel has no poses to interpolate");
  try {
    return make_pose_track(scene, keys);
  } catch (const NoSamBetweenPoses& error) {
    throw refuse(scene::no_sam_reason(error, keys.method));
  } catch (const std::invalid_argument& error) {
    throw refuse(error.what());
  }
}

// The motion of the panel's keyframes, points or poses, refused with NoMotion
// (at the panel's motion pointer) when the method has none through them.
BuiltMotion build_kind(const scene::Scene& scene, const scene::Panel& panel, const std::string& label) {
  const auto refuse = [&](const std::string& reason) { return NoMotion(scene.path, panel.motion_pointer, reason); };
  return std::visit(
      overloaded{
          [&](const scene::KeyframeKeys& given) -> BuiltMotion {
            try {
              std::optional<Chain> chain = chain_of(panel);
              return ArrowTrack{make_motion(given.method, given.keyframes, given.options, given.chain), chain};
            } catch (const MotionDomainError& error) {
              throw refuse(fmt::format("method {} has no motion through these keyframes: {}", label, error.what()));
            } catch (const std::invalid_argument& error) {
              throw refuse(fmt::format("method {} refuses these keyframes: {}", label, error.what()));
            }
          },
          [&](const scene::PointKeys&) -> BuiltMotion {
            if (!panel.timing.is_identity()) {
              throw NoMotion(scene.path, panel.timing.pointer,
                             "timing paces keyframes and poses; a panel of \"points\" has none");
            }
            return PointTrack{std::make_shared<const PointCurveMotion>(point_curve(scene, panel, PointCurve::pita)),
                              chain_of(panel)};
          },
          [&](const scene::PlanePoseKeys& given) -> BuiltMotion { return build_poses(scene, panel, given); },
          [&](const scene::SpacePoseKeys& given) -> BuiltMotion { return build_poses(scene, panel, given); }},
      panel.keys);
}

}  // namespace

SceneMotion build_motion(const scene::Scene& scene, const scene::Panel& panel) {
  SceneMotion motion;
  motion.file_ = scene.path;
  motion.label_ = method_label(scene, panel);
  motion.pointer_ = panel.motion_pointer;
  motion.method_id_ = scene::method_id(panel.keys);
  motion.built_ = build_kind(scene, panel, motion.label_);
  motion.knots_ = scene::knots(panel.keys);

  const scene::Timing& timing = panel.timing;
  if (timing.is_identity()) return motion;
  const std::string at = timing.arc_length ? timing.pointer + "/arc_length" : timing.pointer;
  try {
    // The warp, paced by the arc length of a point of the plane or of space.
    const auto warp = [&](const auto& path) {
      return TimeWarp(timing.ease, timing.per, motion.knots_, path ? &path : nullptr);
    };
    const auto plane_warp = [&] {
      std::function<Point(double)> path;
      if (timing.arc_length) path = motion.point_path(*timing.arc_length);
      return warp(path);
    };
    motion.warp_ = std::visit(
        overloaded{[&](const ArrowTrack&) { return plane_warp(); }, [&](const PointTrack&) { return plane_warp(); },
                   [&](const PlanePoses&) { return plane_warp(); },
                   [&](const SpacePoses&) {
                     ArcLengthTable::Path3 path;
                     if (timing.arc_length) {
                       path = motion.pose_point_path<Affine3>(*timing.arc_length);
                     }
                     return warp(path);
                   }},
        motion.built_);
  } catch (const NoMotion&) {
    throw;
  } catch (const std::exception& error) {
    throw NoMotion(motion.file_, at,
                   fmt::format("cannot pace {} by the arc length of {}: {}", motion.label_,
                               point_name(timing.arc_length.value_or(scene::TrackedPoint::start)), error.what()));
  }
  return motion;
}

void SceneMotion::not_of_kind(std::string_view wanted) const {
  const auto refuse = [&](std::string_view kind) {
    throw NoMotion(file_, pointer_, fmt::format("this motion is of {}, not of {}", kind, wanted));
  };
  std::visit(overloaded{[&](const ArrowTrack&) { refuse("keyframe arrows"); },
                        [&](const PointTrack&) {
                          if (wanted == "keyframe arrows") {
                            throw NoMotion(file_, pointer_,
                                           "this panel has timed \"points\", not keyframes: draw it with a "
                                           "\"point-trajectory\" layer");
                          }
                          refuse("timed points");
                        },
                        [&](const PlanePoses&) { refuse(PoseTraits<Affine2>::noun); },
                        [&](const SpacePoses&) {
                          // A 3D scene asked for work in the plane: its "dimension" is at fault.
                          throw NoMotion(file_, "/dimension",
                                         "this is a 3D pose scene: this command works on poses of the plane only");
                        }},
             built_);
  throw NoMotion(file_, pointer_, fmt::format("this motion is not of {}", wanted));  // not reached
}

template <class Kind>
const Kind& SceneMotion::as(std::string_view wanted) const {
  if (const Kind* kind = std::get_if<Kind>(&built_)) return *kind;
  not_of_kind(wanted);
}

std::optional<Chain> SceneMotion::chain() const {
  return std::visit(overloaded{[](const ArrowTrack& track) { return track.chain; },
                               [](const PointTrack& track) { return track.chain; },
                               [](const PlanePoses&) { return std::optional<Chain>(); },
                               [](const SpacePoses&) { return std::optional<Chain>(); }},
                    built_);
}

const Motion& SceneMotion::arrows() const { return *as<ArrowTrack>("keyframe arrows").motion; }

std::function<Point(double)> SceneMotion::point_path(scene::TrackedPoint point) const {
  using Path = std::function<Point(double)>;
  return std::visit(overloaded{[&](const ArrowTrack& track) -> Path {
                                 return [motion = track.motion, point](double tau) {
                                   return tracked(motion->at(tau), point);
                                 };
                               },
                               [&](const PointTrack&) -> Path { not_of_kind("keyframe arrows"); },
                               [&](const PlanePoses&) -> Path { return pose_point_path<Affine2>(point); },
                               [&](const SpacePoses&) -> Path { not_of_kind("poses of the plane"); }},
                    built_);
}

template <class Pose>
std::function<typename PoseTraits<Pose>::BodyPoint(double)> SceneMotion::pose_point_path(
    scene::TrackedPoint point) const {
  const PoseTrack<Pose>& poses = as<PoseTrack<Pose>>(PoseTraits<Pose>::noun);
  const auto& reference = poses.reference;
  const typename PoseTraits<Pose>::BodyPoint origin =
      point == scene::TrackedPoint::start ? reference[0]
      : point == scene::TrackedPoint::end ? reference[1]
                                          : typename PoseTraits<Pose>::BodyPoint(0.5 * (reference[0] + reference[1]));
  return [motion = poses.motion, origin](double tau) { return pita::apply(motion->at(tau), origin); };
}

SceneMotion build_motion(const scene::Scene& scene) { return build_motion(scene, scene::scene_panel(scene)); }

void SceneMotion::undefined(double t, const std::exception& error) const {
  // A pose PITA says which poses it formed have no SAM (core/pose_pitas).
  const auto* no_sam = dynamic_cast<const NoSamBetweenPoses*>(&error);
  if (no_sam != nullptr && !no_sam->where().empty()) {
    throw NoMotion(file_, pointer_,
                   fmt::format("method {} is undefined at t = {}: {} ({})", label_, t, error.what(), no_sam->where()));
  }
  throw NoMotion(file_, pointer_, fmt::format("method {} is undefined at t = {}: {}", label_, t, error.what()));
}

Point SceneMotion::point_at(double t) const {
  const PointCurveMotion& curve = *as<PointTrack>("timed points").curve;
  Point point;
  try {
    point = curve.at(t);
  } catch (const std::exception& error) {
    undefined(t, error);
  }
  if (!std::isfinite(point.real()) || !std::isfinite(point.imag())) {
    throw NoMotion(file_, pointer_,
                   fmt::format("the curve of {} through these points has no finite point at t = {}: its numbers "
                               "overflow double precision there (t too far outside the knots, or knots very uneven)",
                               label_, t));
  }
  return point;
}

Arrow SceneMotion::arrow_at(double t) const {
  const Motion& motion = arrows();
  Arrow arrow;
  try {
    arrow = motion.at(warp_(t));
  } catch (const std::exception& error) {
    undefined(t, error);
  }
  // q = p + m e^{iw} is finite when p, m and w are and neither |p| nor m is
  // near the largest double; only then is it worth computing.
  constexpr double huge = limits::kHugeCoordinate;
  const bool finite =
      is_finite(arrow) && ((std::abs(arrow.p.real()) < huge && std::abs(arrow.p.imag()) < huge && arrow.m < huge) ||
                           (std::isfinite(arrow.q().real()) && std::isfinite(arrow.q().imag())));
  if (!finite) {
    throw NoMotion(file_, pointer_,
                   fmt::format("method {} has no finite frame at t = {}: its numbers overflow double "
                               "precision there (t too far outside the knots, knots very uneven, or "
                               "magnitudes of very different sizes)",
                               label_, t));
  }
  return arrow;
}

template <class Pose>
const typename PoseTraits<Pose>::Motion& SceneMotion::poses() const {
  return *as<PoseTrack<Pose>>(PoseTraits<Pose>::noun).motion;
}

// A pose motion's pose at scene time t, refused with NoMotion when the
// method throws or the pose is not finite.
template <class Pose>
Pose SceneMotion::pose_at(double t) const {
  const auto& motion = poses<Pose>();
  Pose pose;
  try {
    pose = motion.at(warp_(t));
  } catch (const std::exception& error) {
    undefined(t, error);
  }
  if (!pose.L.allFinite() || !pose.b.allFinite()) {
    throw NoMotion(file_, pointer_,
                   fmt::format("method {} has no finite pose at t = {}: its numbers overflow double "
                               "precision there (t far outside the knots, or poses of extreme scales)",
                               label_, t));
  }
  return pose;
}

template <class Pose>
Pose SceneMotion::pose_velocity(double t) const {
  const auto& motion = poses<Pose>();
  Pose rate;
  try {
    rate = motion.velocity(warp_(t));
  } catch (const std::exception& error) {
    undefined(t, error);
  }
  if (!warp_.is_identity()) {  // dA/dt = dA/dtau dtau/dt
    const double slope = warp_rate(t);
    rate.L *= slope;
    rate.b *= slope;
  }
  return rate;
}

template const PoseMotion& SceneMotion::poses<Affine2>() const;
template const SamFamilyMotion<Affine3>& SceneMotion::poses<Affine3>() const;
template Affine2 SceneMotion::pose_at<Affine2>(double) const;
template Affine3 SceneMotion::pose_at<Affine3>(double) const;
template Affine2 SceneMotion::pose_velocity<Affine2>(double) const;
template Affine3 SceneMotion::pose_velocity<Affine3>(double) const;
template std::function<Point(double)> SceneMotion::pose_point_path<Affine2>(scene::TrackedPoint) const;
template std::function<Eigen::Vector3d(double)> SceneMotion::pose_point_path<Affine3>(scene::TrackedPoint) const;

double SceneMotion::warp_rate(double t) const {
  // d tau / d t by a central difference (the ease and the arc-length inverse
  // are smooth inside each span).
  const double h = limits::kWarpRateStep * (last() - first());
  return central_derivative(warp_, t, h);
}

}  // namespace pita::motion
