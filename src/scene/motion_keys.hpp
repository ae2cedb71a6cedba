// What a panel's motion is made of, as the scene gives it: one alternative per
// kind of motion (timed arrows, timed points, poses of the plane, poses of
// space). The kind of a scene or panel is which alternative it holds; its
// figure data (scene/figure.hpp) are of the kind's family, and figure_of
// (scene.hpp) takes that family from the keys' type. A site whose work depends on the kind visits the variant
// with one overload per alternative (core/overloaded.hpp), so that a kind it
// leaves out does not compile; a site that concerns one kind asks for it with
// std::get_if. The motion stage builds motion::BuiltMotion from these.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/arrow.hpp"
#include "core/chains/chain.hpp"
#include "core/keyframe.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pitas/registry.hpp"
#include "core/point_curves.hpp"
#include "core/pose_method.hpp"
#include "core/pose_motion.hpp"
#include "core/pose_traits.hpp"
#include "core/sam_family_motion.hpp"

namespace pita::scene {

// A PITA and how it is applied: what keyframes and points share.
struct TrackMethod {
  Method method = Method::P6;
  MethodOptions options;       // every field set (defaults applied)
  std::optional<Chain> chain;  // unset: the method's default past its own keyframe count
};

// "keyframes": timed arrows (the PITA paper), knots strictly increasing.
struct KeyframeKeys : TrackMethod {
  std::vector<Keyframe> keyframes;
  // Moving keyframes {"t", "from", "to"} (PITA Sec. 7.4): keyframes[i].arrow
  // is "from", keyframes_to[i] is "to". Empty when no keyframe moves.
  std::vector<Arrow> keyframes_to;
  // "handle" (PITA Sec. 7.1): the arrow that carries the shapes; unset: the first keyframe.
  std::optional<Arrow> given_handle;

  Arrow handle() const { return given_handle.value_or(keyframes.front().arrow); }
  // How many keyframes the method's track runs through.
  std::size_t track_length() const { return keyframes.size(); }
};

// "points": timed points (PITA Sec. 7.6, Fig. 29), at least 4.
struct PointKeys : TrackMethod {
  std::vector<TimedPoint> points;

  // A curve through n points chains n - 1 edge arrows (docs/paper-notes.md N34).
  std::size_t track_length() const { return points.size() - 1; }
};

// "poses": timed affine poses (the SAM paper), in the plane (Affine2) or in
// space (Affine3, "dimension": 3). Empty when the scene only draws figures
// that need no motion.
template <class Pose>
struct PoseKeys {
  PoseMethod method = PoseMethod::sam;
  std::vector<TimedPoseOf<Pose>> poses;
  int subdivisions = kDefaultSubdivisions;  // four-point-SAM: steps
};
using PlanePoseKeys = PoseKeys<Affine2>;
using SpacePoseKeys = PoseKeys<Affine3>;

using MotionKeys = std::variant<KeyframeKeys, PointKeys, PlanePoseKeys, SpacePoseKeys>;

// The canonical id of the keys' method: "P6", "SAM".
std::string method_id(const MotionKeys& keys);

// The JSON field the keys come from: "/keyframes", "/points" or "/poses".
const char* keys_field(const MotionKeys& keys);

// "arrows", "points", "poses", "poses3d": the kind of the keys, as every
// output names it (pita measure's "kind", the Python module's Scene.kind and
// Motion.kind).
std::string_view kind_name(const MotionKeys& keys);

// The knots of the keys (keyframe, point or pose times), increasing:
// keyframes "as-given" may come in any order (docs/paper-notes.md N41), and
// their motion runs from the least to the greatest. Empty for a pose scene
// without poses.
std::vector<double> knots(const MotionKeys& keys);

// The PITA of keyframes or points; nullptr for poses.
TrackMethod* track_method(MotionKeys& keys);
const TrackMethod* track_method(const MotionKeys& keys);

// Whether there is a motion to build from the keys: keyframes and points
// always; poses when any are given (a pose scene may draw only figures that
// need no motion, docs/reference/pose-scenes.md "Pose scenes").
bool has_motion_keys(const MotionKeys& keys);

}  // namespace pita::scene
