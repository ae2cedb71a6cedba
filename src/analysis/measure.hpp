// `pita measure`: goodness measures of a scene's motions as numbers (PITA
// paper Sec. 6, SAM paper Sec. 2.4 and 6; docs/paper-notes.md N37):
//   - discrepancy E (PITA Eq. 47) of each frame against its prediction by the three
//     predictors of Sec. 6.1 (max, mean, t of the max);
//   - path length and total turning of p and q;
//   - the winding range;
//   - overreaction (Sec. 6.4): per keyframe parameter, the largest frame
//     displacement per unit tweak (central differences, similarity-invariant);
//   - pops (Sec. 4.7): the largest jump of a frame under a 1e-9 tweak;
//   - pose motions: ARA (SAM paper Sec. 2.4) and whether the area (det of the
//     linear part) varies monotonically (SAM paper Sec. 6).
// A panel whose motion does not exist is reported (no_motion), not thrown.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/pose_traits.hpp"
#include "motion/scene_motion.hpp"
#include "motion/stage.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {

// Sampling of the measures (named, one place; docs/reference/measure.md "pita measure").
struct MeasureOptions {
  // Times over [t_0, t_n] at which overreaction and pops compare frames.
  int tweak_samples = 65;
  // Dense samples of the paths (length, turning), winding range and area.
  int path_samples = 2048;
  // Central-difference step of overreaction, relative (a position moves by
  // step x extent, a knot by step x (t_n - t_0), m by the factor e^step, w by
  // step radians): small against the motion's curvature in its parameters,
  // large against rounding (1e-16 / 1e-6 = 1e-10 of relative error).
  double gain_step = 1e-6;
  // The tweak of the pop test (Sec. 4.7), same units, both signs.
  double pop_step = 1e-9;
};

// A jump under +-pop_step counts as a pop when it exceeds both
// kPopAbsolute (1e3 times the rounding noise of a frame, relative to the
// extent) and kPopRatio times what the smooth gain predicts (2 pop_step gain).
// At a discontinuity the central-difference gain itself straddles the jump
// (gain ~ jump / (2 gain_step)), so the prediction is 1e-3 of the jump.
constexpr double kPopAbsolute = 1e-7;
constexpr double kPopRatio = 100.0;

struct DiscrepancyStats {
  std::string predictor;  // "previous", "average", "pita"
  int frames = 0;         // frames that have a prediction (0: no statistics)
  double max = 0.0;       // E, dimensionless (PITA Eq. 47)
  double mean = 0.0;
  double t_of_max = 0.0;  // scene time of the worst frame
};

struct PathStats {
  double length = 0.0;   // world units
  double turning = 0.0;  // radians: integral of |curvature| ds
  int inflections = 0;   // sign changes of the curvature (PITA Sec. 6.5)
};

// One keyframe parameter's reaction (Sec. 6.4).
struct ParameterReaction {
  std::string name;   // "B.q.x", "A.m", "C.t"
  double gain = 0.0;  // max_t |dD(t)| / extent per unit normalised tweak
  double turn = 0.0;  // max_t |dD(t).w| (radians) per unit normalised tweak: the
                      // orientation's overreaction, large for short frames (Fig. 19)
  double jump = 0.0;  // max_t |D+(t) - D-(t)| / extent under +-pop_step
  bool pop = false;
  bool defined = true;  // false: a tweak leaves the method's domain (counted as a pop)
};

struct AreaStats {
  bool monotone = true;
  double excursion = 0.0;  // largest move against the overall trend, relative to max |det|
  double t_of_excursion = 0.0;
  double first = 0.0, last = 0.0;  // det L at the first and last knot
};

// The measures of a motion through keyframes (arrows): discrepancy of its
// pattern, paths of p and q, winding range, overreaction and pops.
struct ArrowMeasures {
  static constexpr std::string_view kind_name = "arrows";  // in `pita measure`'s JSON and CSV
  int samples = 0;                                         // pattern frames (discrepancy)
  double extent = 0.0;                                     // diameter of the keyframes' endpoints
  std::vector<DiscrepancyStats> discrepancy;
  PathStats path_p, path_q;
  double winding_min = 0.0, winding_max = 0.0;
  std::vector<ParameterReaction> parameters;
  int most_sensitive = -1;  // index into parameters; -1 when none
  int largest_jump = -1;    // index of the largest jump; -1 when none
  bool pops = false;
};

// The measures of a curve through timed points (Sec. 7.6): its path only.
struct PointMeasures {
  static constexpr std::string_view kind_name = "points";
  PathStats path;
};

// The measures of a motion through poses of the plane or of space: ARA
// (SAM paper Sec. 2.4) and whether det L (an area, or a volume in space)
// varies monotonically (SAM paper Sec. 6).
template <class Pose>
struct PoseMeasures {
  static constexpr std::string_view kind_name = PoseTraits<Pose>::kind_name;  // "poses", "poses3d"
  // What det L measures: the name of its table and JSON member.
  static constexpr std::string_view det_name = in_space_v<Pose> ? "volume" : "area";
  double ara = 0.0;
  AreaStats area;
  // How much the velocity of the ARA points jumps: the largest change between
  // consecutive chords of their paths sampled at path_samples times, over
  // the mean chord. A velocity that jumps at a pose (a polySAM's) keeps it
  // near its relative jump; a smooth motion's shrinks as samples grow.
  double velocity_jump = 0.0;
};

// One alternative per alternative of scene::MotionKeys, in its order: what
// is measured depends on the kind of the panel's keys, and the writers visit it.
using KindMeasures = std::variant<ArrowMeasures, PointMeasures, PoseMeasures<Affine2>, PoseMeasures<Affine3>>;

struct MotionMeasures {
  std::string pointer;                   // the panel's JSON Pointer ("" for the scene itself)
  std::string title;                     // panel title, or ""
  std::string method;                    // "P6 (La-LP)", "SAM"
  std::optional<std::string> no_motion;  // "file: pointer: reason" when it does not exist
  // The kind's measures; default values (nothing measured) when no_motion is set.
  KindMeasures measured;
};

// "arrows", "points", "poses", "poses3d": the "kind" of `pita measure`'s JSON and CSV.
std::string_view measured_kind_name(const MotionMeasures& measures);

// The overreaction of each keyframe parameter: empty but for keyframes.
std::span<const ParameterReaction> parameters_of(const MotionMeasures& measures);

// The diameter of the set of keyframe endpoints {p, q}: the length unit of
// the similarity-invariant measures. > 0 since every m > 0.
double keyframe_extent(const std::vector<Keyframe>& keyframes);

// Length and total turning of a curve sampled at points[1 .. n+1] (n + 1
// evenly spaced parameters over its range; points[0] and points[n+2] one step
// beyond each end): polyline length, and the sum of the angles
// between consecutive tangents (central differences; a zero tangent is
// skipped): exact turning for a circle arc, 0 for a straight segment. Its
// inflections: how often the side the curve turns to changes, a turn below
// kStraightTurn radians counting as straight (no side): 0 for a circle, a
// parabola or a log spiral, 1 for y = x^3 through 0, 2k - 1 for k half
// periods of a sine.
inline constexpr double kStraightTurn = 1e-9;
PathStats path_stats(std::span<const Point> points);

// Area monotonicity of det L(t) at the given samples.
AreaStats area_stats(const std::vector<double>& times, const std::vector<double>& dets);

// What measure_panel costs, in frames of a plain method (motion::frame_cost):
// per keyframe parameter four tweaked motions, each built (about two frames
// per keyframe: a copy of the panel and the track's preparation) and sampled
// tweak_samples times, plus the dense path and the
// pattern's three predictors. What `pita measure` and the render budget weigh.
double measure_cost(const scene::Panel& panel, const MeasureOptions& options = {});

// Measures of the motion of the stage's panel `index`; never throws
// NoMotion (no_motion is set).
MotionMeasures measure_panel(const motion::Stage& stage, std::size_t index, const MeasureOptions& options = {});

// Refuses (scene::SceneError at /panels, or /keyframes for a scene without
// panels) a scene whose measure_cost over every panel exceeds
// scene::kMaxEvalWork: what `pita measure` checks before measuring.
void check_measure_work(const scene::Scene& scene, const MeasureOptions& options = {});

// Every panel of the scene (the scene itself when it has no panels).
std::vector<MotionMeasures> measure_scene(const scene::Scene& scene, const MeasureOptions& options = {});

}  // namespace pita::analysis
