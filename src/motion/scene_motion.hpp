// The motion stage: the motion of a scene (or of one panel of it), built once
// from the resolved scene model, arrows or poses alike, with its time warp.
// Everything that evaluates a motion (eval, render, golden, analysis) goes
// through here:
//
//   scene file -> scene model (src/scene) -> SceneMotion (built once) ->
//   timed samples (sampler.hpp) -> layers, numbers, figures
//
// Times given to a SceneMotion are scene times; it evaluates the underlying
// method at the warped time tau = warp(t) ("timing", README "Timing").
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/affine2.hpp"
#include "core/arrow.hpp"
#include "core/pitas/motion.hpp"
#include "core/point_curves.hpp"
#include "core/pose_motion.hpp"
#include "core/sam_family_motion.hpp"
#include "core/time_warp.hpp"
#include "motion/no_motion.hpp"
#include "scene/scene.hpp"

namespace pita::motion {

class SceneMotion {
 public:
  scene::SceneKind kind() const { return kind_; }
  // The canonical method id ("P6", "SAM") and how messages name it ("P6 (La-LP)").
  const std::string& method_id() const { return method_id_; }
  const std::string& label() const { return label_; }
  // Arrow scenes of timed "points" (PITA Sec. 7.6): the PITA curve through
  // them (Eq. 48-50 with the panel's method and chain) at scene time t.
  // arrow_at throws NoMotion for them.
  bool has_points() const { return static_cast<bool>(points_); }
  Point point_at(double t) const;

  // Arrow scenes: the chain that extends the method past its own keyframe
  // count (core/chains/chain.hpp), nullopt when the method is used alone.
  std::optional<Chain> chain() const { return chain_; }
  // The knots (keyframe or pose times), strictly increasing.
  const std::vector<double>& knots() const { return knots_; }
  double first() const { return knots_.front(); }
  double last() const { return knots_.back(); }

  // The motion's own time at scene time t.
  double motion_time(double t) const { return warp_(t); }
  const TimeWarp& warp() const { return warp_; }

  // D(t) (arrow scenes) and A(t) (pose scenes) at scene time t. Throw
  // NoMotion when the method is undefined there or its value is not finite.
  Arrow arrow_at(double t) const;
  Affine2 pose_at(double t) const;
  // 3D pose scenes ("dimension": 3): A(t) in space. pose_at, pose_velocity
  // and point_path throw NoMotion for them, pose3_at for every other scene.
  bool in_space() const { return static_cast<bool>(poses3_); }
  Affine3 pose3_at(double t) const;
  Affine3 pose3_velocity(double t) const;  // dA/dt at scene time t, the warp's rate included
  // dA/dt at scene time t (pose scenes), the warp's rate included.
  Affine2 pose_velocity(double t) const;

  // The path of a point of the frame as a function of the motion's own time
  // tau (no warp): for arrows p, q or their midpoint; for poses the images of
  // the reference triangle's first point, second point, or their midpoint.
  std::function<Point(double)> point_path(scene::TrackedPoint point) const;
  // 3D pose scenes: the images of the reference tetrahedron's first point,
  // second point, or their midpoint, as functions of tau.
  std::function<Eigen::Vector3d(double)> point_path3(scene::TrackedPoint point) const;

  // The method's motion without the warp (for analysis and tests).
  const Motion& arrows() const { return *arrows_; }
  const PoseMotion& poses() const { return *poses_; }

  // File and JSON Pointer this motion's errors name.
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }

 private:
  friend SceneMotion build_motion(const scene::Scene&, const scene::Panel&);
  friend SceneMotion build_motion(const scene::Scene&);
  SceneMotion() = default;
  [[noreturn]] void undefined(double t, const std::exception& error) const;
  void require_plane() const;  // NoMotion for a 3D scene
  double warp_rate(double t) const;  // d tau / d t
  template <class Motion>
  auto finite_pose(const Motion& motion, double t) const;

  scene::SceneKind kind_ = scene::SceneKind::arrows;
  std::string method_id_, label_;
  std::vector<double> knots_;
  std::optional<Chain> chain_;
  std::shared_ptr<const Motion> arrows_;
  std::shared_ptr<const PoseMotion> poses_;
  std::shared_ptr<const PoseMotion3> poses3_;
  std::shared_ptr<const PointCurveMotion> points_;
  TimeWarp warp_;
  std::array<Point, 3> reference_{};  // poses: the reference triangle
  std::array<Eigen::Vector3d, 4> reference3_{};  // 3D poses: the reference tetrahedron
  std::string file_, pointer_;
};

// The motion of `panel` (its method, keyframes or poses, options and timing).
// The only place motions are built from a scene. Throws NoMotion: the method
// refuses the keyframes, no SAM exists between two poses, the panel has no
// poses, or the arc-length path has zero length (at the timing's pointer).
SceneMotion build_motion(const scene::Scene& scene, const scene::Panel& panel);
// The scene's own motion (its method, keyframes or poses, and timing).
SceneMotion build_motion(const scene::Scene& scene);

// Builds the motion of every panel that draws one (pose panels without poses
// draw none), so that a scene is judged alike by every command. Throws
// NoMotion for the first that does not exist.
void check_motions(const scene::Scene& scene);

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
