// The motion stage: the motion of a scene (or of one panel of it), built once
// from the resolved scene model, arrows or poses alike, with its time warp.
// Everything that evaluates a motion (eval, render, golden, analysis) goes
// through here:
//
//   scene file -> scene model (src/scene) -> SceneMotion (built once) ->
//   timed samples (sampler.hpp) -> layers, numbers, figures
//
// Times given to a SceneMotion are scene times; it evaluates the underlying
// method at the warped time tau = warp(t) ("timing", docs/reference/scene-format.md "Timing").
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/affine2.hpp"
#include "core/arrow.hpp"
#include "core/pitas/motion.hpp"
#include "core/point_curves.hpp"
#include "core/pose_motion.hpp"
#include "core/pose_traits.hpp"
#include "core/sam_family_motion.hpp"
#include "core/time_warp.hpp"
#include "motion/no_motion.hpp"
#include "scene/scene.hpp"

namespace pita::motion {

// The motion of a panel, built: one alternative per kind of motion. A site
// whose work depends on the kind visits it (std::visit with one overload per
// alternative, core/overloaded.hpp), so that a kind it leaves out does not
// compile. The motions are immutable and shared by copies of a SceneMotion.
struct ArrowTrack {  // keyframe arrows (the PITA paper): D(tau)
  std::shared_ptr<const Motion> motion;
  std::optional<Chain> chain;  // the chain past the method's own keyframe count
};
struct PointTrack {  // timed points (PITA Sec. 7.6): the curve of PITA Eq. 48-50
  std::shared_ptr<const PointCurveMotion> curve;
  std::optional<Chain> chain;  // the chain of the edge arrows' track
};
// Poses of the plane (the SAM paper) or of space ("dimension": 3): A(tau).
template <class Pose>
struct PoseTrack {
  std::shared_ptr<const typename PoseTraits<Pose>::Motion> motion;
  typename PoseTraits<Pose>::Simplex reference;  // the reference triangle or tetrahedron
};
using PlanePoses = PoseTrack<Affine2>;
using SpacePoses = PoseTrack<Affine3>;
using BuiltMotion = std::variant<ArrowTrack, PointTrack, PlanePoses, SpacePoses>;

class SceneMotion {
 public:
  // The motion itself, to visit; is<PointTrack>() asks for one kind.
  const BuiltMotion& built() const { return built_; }
  template <class Kind>
  bool is() const {
    return std::holds_alternative<Kind>(built_);
  }

  // The canonical method id ("P6", "SAM") and how messages name it ("P6 (La-LP)").
  const std::string& method_id() const { return method_id_; }
  const std::string& label() const { return label_; }

  // Timed points: the PITA curve through them (PITA Eq. 48-50 with the panel's
  // method and chain) at scene time t. Throws NoMotion for other kinds.
  Point point_at(double t) const;

  // Keyframes and points: the chain that extends the method past its own
  // keyframe count (core/chains/chain.hpp); nullopt when the method is used
  // alone, and for poses.
  std::optional<Chain> chain() const;
  // The knots (keyframe, point or pose times), strictly increasing.
  const std::vector<double>& knots() const { return knots_; }
  double first() const { return knots_.front(); }
  double last() const { return knots_.back(); }

  // The motion's own time at scene time t.
  double motion_time(double t) const { return warp_(t); }
  const TimeWarp& warp() const { return warp_; }

  // D(t) (keyframes) at scene time t, and A(t) and dA/dt (poses of the plane,
  // Pose = Affine2, or of space, Affine3; the warp's rate included in dA/dt).
  // Throw NoMotion when the method is undefined there, its value is not
  // finite, or the motion is of another kind.
  Arrow arrow_at(double t) const;
  template <class Pose>
  Pose pose_at(double t) const;
  template <class Pose>
  Pose pose_velocity(double t) const;

  // The path of a point of the frame as a function of the motion's own time
  // tau (no warp): for arrows p, q or their midpoint; for poses the images of
  // the reference simplex's first point, second point, or their midpoint.
  // Throws NoMotion for timed points.
  std::function<Point(double)> point_path(scene::TrackedPoint point) const;
  template <class Pose>
  std::function<typename PoseTraits<Pose>::BodyPoint(double)> pose_point_path(scene::TrackedPoint point) const;

  // The method's motion without the warp (for analysis and tests). Throw
  // NoMotion for a motion of another kind.
  const Motion& arrows() const;
  template <class Pose>
  const typename PoseTraits<Pose>::Motion& poses() const;

  // File and JSON Pointer this motion's errors name.
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }

 private:
  friend SceneMotion build_motion(const scene::Scene&, const scene::Panel&);
  friend SceneMotion build_motion(const scene::Scene&);
  SceneMotion() = default;
  [[noreturn]] void undefined(double t, const std::exception& error) const;
  [[noreturn]] void not_of_kind(std::string_view wanted) const;
  template <class Kind>
  const Kind& as(std::string_view wanted) const;
  double warp_rate(double t) const;  // d tau / d t

  BuiltMotion built_;
  std::string method_id_, label_;
  std::vector<double> knots_;
  TimeWarp warp_;
  std::string file_, pointer_;
};

// The motion of `panel` (its method, keyframes or poses, options and timing).
// The only place motions are built from a scene; outside src/motion/ they
// come from a Stage (motion/stage.hpp). Throws NoMotion: the method
// refuses the keyframes, no SAM exists between two poses, the panel has no
// poses, or the arc-length path has zero length (at the timing's pointer).
SceneMotion build_motion(const scene::Scene& scene, const scene::Panel& panel);
// The scene's own motion (its method, keyframes or poses, and timing).
SceneMotion build_motion(const scene::Scene& scene);

// What one frame of the panel's motion costs, in frames of a plain method
// (chain_frame_cost; a curve through points evaluates two tracks): what the
// work limits of `pita eval` and `pita render` weigh frames by.
double frame_cost(const scene::Panel& panel);

// The chain the panel's arrow motion uses: its "chain", else the method's
// default when the panel has more keyframes than the method takes, else none.
std::optional<Chain> chain_of(const scene::Panel& panel);

// The curve `curve` through the panel's timed points; for PointCurve::pita the
// tracks are the panel's method, options and chain (docs/paper-notes.md N34).
// Throws NoMotion (at the panel's points) when the curve cannot be built.
PointCurveMotion point_curve(const scene::Scene& scene, const scene::Panel& panel, PointCurve curve);

// "P6 (La-LP)", "SMA", "SAM", "P6 (La-LP), blend chain": a method as messages name it.
std::string method_label(const scene::Scene& scene, const scene::Panel& panel);

}  // namespace pita::motion
