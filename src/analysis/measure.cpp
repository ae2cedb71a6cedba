#include "analysis/measure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

#include <Eigen/LU>
#include <fmt/format.h>

#include "analysis/arrow_distance.hpp"
#include "analysis/prediction.hpp"
#include "core/discrepancy.hpp"
#include "core/overloaded.hpp"
#include "core/steadiness.hpp"
#include "motion/sampler.hpp"
#include "motion/stage.hpp"
#include "scene/body_points.hpp"

namespace pita::analysis {

namespace {

// "A", "B", ..., "Z", then "K27", "K28", ...: keyframe names (Sec. 1).
std::string keyframe_name(std::size_t index) {
  if (index < 26) return std::string(1, static_cast<char>('A' + index));
  return fmt::format("K{}", index + 1);
}

// The seven parameters of a keyframe (docs/paper-notes.md N37): p.x, p.y
// translate the arrow (m, w kept: a drag near p, Sec. 6.3); q.x, q.y move the
// tip with p kept (a drag near q; w follows continuously); m is scaled by
// e^delta; w turns by delta radians; t is the knot.
enum class Parameter { px, py, qx, qy, m, w, t };
constexpr std::array<Parameter, 7> kParameters{Parameter::px, Parameter::py, Parameter::qx, Parameter::qy,
                                               Parameter::m,  Parameter::w,  Parameter::t};
constexpr std::array<const char*, 7> kParameterNames{"p.x", "p.y", "q.x", "q.y", "m", "w", "t"};

// Keyframe `key` with parameter `which` moved by the normalised `delta`.
Keyframe tweaked(Keyframe key, Parameter which, double delta, double extent, double duration) {
  Arrow& arrow = key.arrow;
  switch (which) {
    case Parameter::px:
      arrow.p += Complex{delta * extent, 0.0};
      break;
    case Parameter::py:
      arrow.p += Complex{0.0, delta * extent};
      break;
    case Parameter::qx:
    case Parameter::qy: {
      const Vector before = arrow.vector();
      const Vector after =
          before + (which == Parameter::qx ? Complex{delta * extent, 0.0} : Complex{0.0, delta * extent});
      arrow.m = std::abs(after);
      arrow.w += std::arg(after / before);  // the winding follows the tip continuously
      break;
    }
    case Parameter::m:
      arrow.m *= std::exp(delta);
      break;
    case Parameter::w:
      arrow.w += delta;
      break;
    case Parameter::t:
      key.t += delta * duration;
      break;
  }
  return key;
}

double knot_min(const std::vector<Keyframe>& keys) {
  double least = keys.front().t;
  for (const Keyframe& k : keys) least = std::min(least, k.t);
  return least;
}
double knot_max(const std::vector<Keyframe>& keys) {
  double greatest = keys.front().t;
  for (const Keyframe& k : keys) greatest = std::max(greatest, k.t);
  return greatest;
}

// The frames of the panel with keyframe `index`'s parameter moved by delta,
// at `times`; nullopt when that motion does not exist.
std::optional<std::vector<Arrow>> tweaked_frames(const scene::Scene& scene, const scene::Panel& panel,
                                                 std::size_t index, Parameter which, double delta, double extent,
                                                 double duration, const std::vector<double>& times) {
  // The method's own motion: the timing only paces it (docs/paper-notes.md N37).
  const std::vector<Keyframe>& given = std::get<scene::KeyframeKeys>(panel.keys).keyframes;
  std::vector<Keyframe> keys = given;
  keys[index] = tweaked(given[index], which, delta, extent, duration);
  // The tweaked knot keeps its place among the others (increasing, or the
  // order of keyframes "as-given", docs/paper-notes.md N41).
  for (std::size_t j = 0; j < keys.size(); ++j) {
    if (j == index) continue;
    if ((keys[index].t > keys[j].t) != (given[index].t > given[j].t) || keys[index].t == keys[j].t) {
      return std::nullopt;
    }
  }
  try {
    const motion::SceneMotion tweaked_motion = motion::untimed_with_keyframes(scene, panel, keys);
    // A knot tweak compares the patterns: uniform times over the new knots
    // (else moving an end knot would count as shifting every frame's time).
    const std::vector<double> at =
        which == Parameter::t ? motion::uniform_times(knot_min(keys), knot_max(keys), static_cast<int>(times.size()))
                              : times;
    std::vector<Arrow> frames;
    frames.reserve(at.size());
    for (const double t : at) frames.push_back(tweaked_motion.arrow_at(t));
    return frames;
  } catch (const motion::NoMotion&) {
    return std::nullopt;
  }
}

// The largest change of orientation, modulo 2 pi (a frame's turns do not
// show; the tweak is small).
double largest_turn(const std::vector<Arrow>& x, const std::vector<Arrow>& y) {
  double turn = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) turn = std::max(turn, std::abs(principal_angle(x[i].w - y[i].w)));
  return turn;
}

double largest_change(const std::vector<Arrow>& x, const std::vector<Arrow>& y) {
  double change = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) change = std::max(change, endpoint_distance(x[i], y[i]));
  return change;
}

void measure_discrepancy(const scene::Panel& panel, const motion::SceneMotion& motion, ArrowMeasures& out) {
  const scene::TrackMethod& track = std::get<scene::KeyframeKeys>(panel.keys);
  const std::vector<double> times = motion::uniform_times(motion, panel.samples);
  std::vector<Arrow> frames;
  for (const motion::Frame& frame : motion::sample_arrows(motion, times)) frames.push_back(frame.arrow);
  constexpr std::array<std::pair<scene::Predictor, const char*>, 3> kPredictors{
      {{scene::Predictor::previous, "previous"},
       {scene::Predictor::average, "average"},
       {scene::Predictor::pita, "pita"}}};
  for (const auto& [predictor, name] : kPredictors) {
    DiscrepancyStats stats;
    stats.predictor = name;
    double sum = 0.0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      std::optional<double> e;
      try {
        e = frame_discrepancy(predictor, track.method, track.options, times, frames, i);
      } catch (const std::exception&) {
        continue;  // the predicting motion does not exist through these frames
      }
      if (!e || !std::isfinite(*e)) continue;
      if (stats.frames == 0 || *e > stats.max) {
        stats.max = *e;
        stats.t_of_max = times[i];
      }
      sum += *e;
      ++stats.frames;
    }
    if (stats.frames > 0) stats.mean = sum / stats.frames;
    out.discrepancy.push_back(stats);
  }
}

// Dense arrows over the motion's own time, one step past each end.
std::vector<Arrow> dense_arrows(const motion::SceneMotion& motion, int samples) {
  const double first = motion.first(), step = (motion.last() - first) / samples;
  std::vector<Arrow> arrows;
  arrows.reserve(static_cast<std::size_t>(samples) + 3);
  for (int i = -1; i <= samples + 1; ++i) {
    const double tau = i == samples ? motion.last() : first + step * i;
    arrows.push_back(motion.arrows().at(tau));
  }
  return arrows;
}

void measure_paths(const motion::SceneMotion& motion, const MeasureOptions& options, ArrowMeasures& out) {
  const std::vector<Arrow> arrows = dense_arrows(motion, options.path_samples);
  std::vector<Point> p, q;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < arrows.size(); ++i) {
    if (!is_finite(arrows[i])) throw std::domain_error("a frame is not finite");
    p.push_back(arrows[i].p);
    q.push_back(arrows[i].q());
    if (i > 0 && i + 1 < arrows.size()) {
      lo = std::min(lo, arrows[i].w);
      hi = std::max(hi, arrows[i].w);
    }
  }
  out.path_p = path_stats(p);
  out.path_q = path_stats(q);
  out.winding_min = lo;
  out.winding_max = hi;
}

void measure_reactions(const scene::Scene& scene, const scene::Panel& panel, const motion::SceneMotion& motion,
                       const MeasureOptions& options, ArrowMeasures& out) {
  // Motion times (the timing is left out, docs/paper-notes.md N37).
  const std::vector<double> times = motion::uniform_times(motion.first(), motion.last(), options.tweak_samples);
  const double extent = out.extent, duration = motion.last() - motion.first();
  double best_gain = -1.0, best_jump = -1.0;
  for (std::size_t k = 0; k < std::get<scene::KeyframeKeys>(panel.keys).keyframes.size(); ++k) {
    for (std::size_t j = 0; j < kParameters.size(); ++j) {
      ParameterReaction reaction;
      reaction.name = keyframe_name(k) + "." + kParameterNames[j];
      const auto plus = tweaked_frames(scene, panel, k, kParameters[j], options.gain_step, extent, duration, times);
      const auto minus = tweaked_frames(scene, panel, k, kParameters[j], -options.gain_step, extent, duration, times);
      const auto pop_plus = tweaked_frames(scene, panel, k, kParameters[j], options.pop_step, extent, duration, times);
      const auto pop_minus =
          tweaked_frames(scene, panel, k, kParameters[j], -options.pop_step, extent, duration, times);
      if (!plus || !minus || !pop_plus || !pop_minus) {
        reaction.defined = false;  // a tweak leaves the method's domain: a pop of its own kind
        reaction.pop = true;
        out.pops = true;
        out.parameters.push_back(reaction);
        continue;
      }
      reaction.gain = largest_change(*plus, *minus) / extent / (2.0 * options.gain_step);
      reaction.turn = largest_turn(*plus, *minus) / (2.0 * options.gain_step);
      reaction.jump = largest_change(*pop_plus, *pop_minus) / extent;
      if (!std::isfinite(reaction.gain) || !std::isfinite(reaction.turn) || !std::isfinite(reaction.jump)) {
        reaction.gain = reaction.turn = reaction.jump = 0.0;
        reaction.defined = false;  // a tweak gives frames that are not finite: a pop of its own kind
        reaction.pop = true;
        out.pops = true;
        out.parameters.push_back(reaction);
        continue;
      }
      const double predicted = 2.0 * options.pop_step * reaction.gain;
      reaction.pop = reaction.jump > kPopAbsolute && reaction.jump > kPopRatio * predicted;
      out.pops = out.pops || reaction.pop;
      if (reaction.gain > best_gain) {
        best_gain = reaction.gain;
        out.most_sensitive = static_cast<int>(out.parameters.size());
      }
      if (reaction.jump > best_jump) {
        best_jump = reaction.jump;
        out.largest_jump = static_cast<int>(out.parameters.size());
      }
      out.parameters.push_back(reaction);
    }
  }
}

// The points whose relative acceleration ARA averages (Sec. 2.4), from the
// body's points (scene::body_points, what the figure draws): in the plane the
// regular grid over their box, as an "ara" layer prints it (N28); in space
// the vertices themselves.
template <class Pose>
std::vector<typename PoseTraits<Pose>::Vector> ara_points(const scene::Scene& scene, const scene::Panel& panel) {
  const auto body = scene::body_points<Pose>(scene, panel);
  if constexpr (!in_space_v<Pose>) {
    std::vector<Eigen::Vector2d> vertices;
    for (const Point& x : body) vertices.emplace_back(x.real(), x.imag());
    return ara_grid(vertices);
  } else {
    return body;
  }
}

// The largest jump of a point's velocity between consecutive samples,
// |c_i - c_(i-1)| for consecutive chords c of the paths of `points` under
// the poses at `times`, over the mean chord of all of them
// (MotionMeasures::velocity_jump); 0 for a body that does not move.
template <class PoseMotionT, class Vector>
double velocity_jump(const PoseMotionT& poses, std::span<const Vector> points, const std::vector<double>& times) {
  std::vector<Vector> previous(points.size()), before(points.size());
  double jump = 0.0, chords = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const auto pose = poses.at(times[i]);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vector x = pita::apply(pose, points[k]);
      if (i >= 1) {
        const Vector chord = x - previous[k];
        chords += chord.norm();
        ++count;
        if (i >= 2) jump = std::max(jump, (chord - before[k]).norm());
        before[k] = chord;
      }
      previous[k] = x;
    }
  }
  const double mean = count > 0 ? chords / static_cast<double>(count) : 0.0;
  return mean > 0.0 ? jump / mean : 0.0;
}

// ARA of the pose motion (its own time, no warp) and the monotonicity of
// det L: the area in the plane, the volume in space. One template for both.
template <class Pose, class PoseMotionT, class Vector>
PoseMeasures<Pose> measure_pose_motion(const PoseMotionT& poses, std::span<const Vector> points, double first,
                                       double last, const MeasureOptions& options) {
  PoseMeasures<Pose> out;
  out.ara = average_relative_acceleration(poses, points);
  std::vector<double> times, dets;
  const double step = (last - first) / options.path_samples;
  for (int i = 0; i <= options.path_samples; ++i) {
    const double tau = i == options.path_samples ? last : first + step * i;
    times.push_back(tau);
    dets.push_back(poses.at(tau).L.determinant());
  }
  out.area = area_stats(times, dets);
  if (!std::isfinite(out.ara)) throw std::domain_error("ARA is not finite");
  out.velocity_jump = velocity_jump(poses, points, times);
  return out;
}

// The measures of the panel's motion, of the alternative its keys have.
KindMeasures measure_motion(const scene::Scene& scene, const scene::Panel& panel, const motion::SceneMotion& motion,
                            const MeasureOptions& options) {
  return std::visit(
      overloaded{[&](const motion::ArrowTrack&) -> KindMeasures {
                   ArrowMeasures out;
                   out.samples = panel.samples;
                   out.extent = keyframe_extent(std::get<scene::KeyframeKeys>(panel.keys).keyframes);
                   measure_discrepancy(panel, motion, out);
                   measure_paths(motion, options, out);
                   measure_reactions(scene, panel, motion, options, out);
                   return out;
                 },
                 [&](const motion::PointTrack&) -> KindMeasures {
                   // A curve through timed points (Sec. 7.6): its path only.
                   const double first = motion.first();
                   const double step = (motion.last() - first) / options.path_samples;
                   std::vector<Point> p;
                   for (int i = -1; i <= options.path_samples + 1; ++i) {
                     p.push_back(motion.point_at(i == options.path_samples ? motion.last() : first + step * i));
                   }
                   return PointMeasures{path_stats(p)};
                 },
                 [&](const motion::PlanePoses& poses) -> KindMeasures {
                   const std::vector<Eigen::Vector2d> points = ara_points<Affine2>(scene, panel);
                   return measure_pose_motion<Affine2>(*poses.motion, std::span<const Eigen::Vector2d>(points),
                                                       motion.first(), motion.last(), options);
                 },
                 [&](const motion::SpacePoses& poses) -> KindMeasures {
                   const std::vector<Eigen::Vector3d> points = ara_points<Affine3>(scene, panel);
                   return measure_pose_motion<Affine3>(*poses.motion, std::span<const Eigen::Vector3d>(points),
                                                       motion.first(), motion.last(), options);
                 }},
      motion.built());
}

// The alternative of the panel's keys with nothing measured.
KindMeasures unmeasured_kind(const scene::MotionKeys& keys) {
  return std::visit(overloaded{[](const scene::KeyframeKeys&) -> KindMeasures { return ArrowMeasures{}; },
                               [](const scene::PointKeys&) -> KindMeasures { return PointMeasures{}; },
                               [](const scene::PlanePoseKeys&) -> KindMeasures { return PoseMeasures<Affine2>{}; },
                               [](const scene::SpacePoseKeys&) -> KindMeasures { return PoseMeasures<Affine3>{}; }},
                    keys);
}

}  // namespace

double keyframe_extent(const std::vector<Keyframe>& keyframes) {
  std::vector<Point> ends;
  for (const Keyframe& key : keyframes) {
    ends.push_back(key.arrow.p);
    ends.push_back(key.arrow.q());
  }
  double diameter = 0.0;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    for (std::size_t j = i + 1; j < ends.size(); ++j) diameter = std::max(diameter, std::abs(ends[i] - ends[j]));
  }
  return diameter;
}

PathStats path_stats(std::span<const Point> points) {
  PathStats stats;
  const std::size_t n = points.size();
  if (n < 3) return stats;
  for (std::size_t i = 1; i + 2 < n; ++i) stats.length += std::abs(points[i + 1] - points[i]);
  // Tangents at the level of rounding (a path that hardly moves) have no
  // direction: they are skipped, not summed as noise.
  double reach = 0.0;
  for (const Point& x : points) reach = std::max(reach, std::abs(x - points.front()));
  const double tiny = 1e-9 * reach;
  std::optional<Vector> previous;
  int side = 0;  // of the last turn that was not straight: +1 left, -1 right
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Vector tangent = points[i + 1] - points[i - 1];
    if (!(std::abs(tangent) > tiny)) continue;
    if (previous) {
      const double turn = std::arg(tangent / *previous);
      stats.turning += std::abs(turn);
      if (std::abs(turn) > kStraightTurn) {
        const int now = turn > 0.0 ? 1 : -1;
        if (side != 0 && now != side) ++stats.inflections;
        side = now;
      }
    }
    previous = tangent;
  }
  return stats;
}

AreaStats area_stats(const std::vector<double>& times, const std::vector<double>& dets) {
  AreaStats stats;
  if (dets.empty()) return stats;
  stats.first = dets.front();
  stats.last = dets.back();
  double scale = 0.0;
  for (const double d : dets) scale = std::max(scale, std::abs(d));
  // Relative rounding of a determinant: moves below this never count.
  constexpr double kAreaTolerance = 1e-9;
  // The trend: rising unless the area clearly falls (equal ends, to rounding,
  // count as rising, so that a dip is measured at its bottom).
  const double sign = stats.last >= stats.first - kAreaTolerance * scale ? 1.0 : -1.0;
  // The largest move against the trend: max over i < j of sign (d_i - d_j).
  double best_so_far = sign * dets.front();
  for (std::size_t j = 0; j < dets.size(); ++j) {
    best_so_far = std::max(best_so_far, sign * dets[j]);
    const double against = best_so_far - sign * dets[j];
    if (against > stats.excursion) {
      stats.excursion = against;
      stats.t_of_excursion = times[j];
    }
  }
  if (scale > 0.0) stats.excursion /= scale;
  stats.monotone = stats.excursion <= kAreaTolerance;
  return stats;
}

double measure_cost(const scene::Panel& panel, const MeasureOptions& options) {
  const double frame = motion::frame_cost(panel);
  // Keyframes are tweaked one parameter at a time; poses are measured one span at a time.
  const auto [keyframes, poses] = std::visit(
      overloaded{[](const scene::KeyframeKeys& given) { return std::pair(given.keyframes.size(), std::size_t{0}); },
                 [](const scene::PointKeys&) { return std::pair(std::size_t{0}, std::size_t{0}); },
                 [](const scene::PlanePoseKeys& given) { return std::pair(std::size_t{0}, given.poses.size()); },
                 [](const scene::SpacePoseKeys& given) { return std::pair(std::size_t{0}, given.poses.size()); }},
      panel.keys);
  const double keys = static_cast<double>(keyframes);
  const double tweaks = 4.0 * static_cast<double>(kParameters.size()) * keys;
  return tweaks * (2.0 * keys + options.tweak_samples * frame) +
         (options.path_samples + 3.0 + 3.0 * panel.samples) * frame +
         static_cast<double>(poses) * (options.path_samples + 64.0);
}

std::string_view measured_kind_name(const MotionMeasures& measures) {
  return std::visit([](const auto& measured) { return std::decay_t<decltype(measured)>::kind_name; },
                    measures.measured);
}

std::span<const ParameterReaction> parameters_of(const MotionMeasures& measures) {
  return std::visit(
      overloaded{[](const ArrowMeasures& arrows) { return std::span(arrows.parameters); },
                 [](const PointMeasures&) { return std::span<const ParameterReaction>(); },
                 []<class Pose>(const PoseMeasures<Pose>&) { return std::span<const ParameterReaction>(); }},
      measures.measured);
}

MotionMeasures measure_panel(const motion::Stage& stage, std::size_t index, const MeasureOptions& options) {
  const scene::Scene& scene = stage.scene();
  const scene::Panel& panel = stage.panel(index);
  MotionMeasures out;
  out.pointer = panel.pointer;
  out.title = panel.title;
  out.method = motion::method_label(scene, panel);
  out.measured = unmeasured_kind(panel.keys);  // nothing half measured when the motion fails
  try {
    out.measured = measure_motion(scene, panel, stage.motion(index), options);
  } catch (const motion::NoMotion& error) {
    out.no_motion = error.what();
  } catch (const std::exception& error) {
    out.no_motion = scene::located(scene.path, panel.motion_pointer,
                                   fmt::format("method {} cannot be measured: {}", out.method, error.what()));
  }
  return out;
}

void check_measure_work(const scene::Scene& scene, const MeasureOptions& options) {
  double work = 0.0;
  for (const scene::Panel& panel : scene.panels) work += measure_cost(panel, options);
  if (work > scene::kMaxEvalWork) {
    throw scene::SceneError(scene.path, scene.panels.size() > 1 ? "/panels" : "/keyframes",
                            fmt::format("measuring these motions costs about {:.3g} frames of a method, above the "
                                        "limit of {:.0g}: fewer keyframes or panels, or the local \"blend\" chain",
                                        work, scene::kMaxEvalWork));
  }
}

std::vector<MotionMeasures> measure_scene(const scene::Scene& scene, const MeasureOptions& options) {
  std::vector<MotionMeasures> all;
  const motion::Stage stage(scene);
  for (std::size_t i = 0; i < stage.size(); ++i) all.push_back(measure_panel(stage, i, options));
  return all;
}

}  // namespace pita::analysis
