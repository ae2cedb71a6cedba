// The names a "measures" layer shows (docs/reference/render.md "Figure fields of a scene", `measures`): the one
// table of them. The reader parses each name once into a MeasureName; the
// renderer switches on its kind and never compares strings.
//
//   "discrepancy-max", "path-length", "turning", "winding-range",
//   "overreaction", "pop", "handle-shift"        arrow scenes
//   "ara", "area", "velocity-jump"                pose scenes
//   "gain:K.x", "turn:K.x", "jump:K.x"           arrow scenes: one keyframe
//       parameter, K a keyframe (A..Z, K27, ...), x one of p, q, p.x, p.y,
//       q.x, q.y, m, w, t ("gain:B.q" is the larger of B.q.x and B.q.y)
//   "angle:M@t"                                   arrow scenes: the angle from
//       the panel's D(t).w to that of arrow method M (Fig. 5), t finite; in a
//       claim M may be another panel, "angle:/panels/1@0.25" (docs/reference/check.md "Claims")
//   "scale-step", "turn-step", "scale-min",       arrow scenes: the frames the
//   "scale-max"                                   pattern draws (analysis/frame_steps.hpp)
//   "frame-distance:/panels/K", "frame-distance:M"  arrow and pose scenes, in a claim:
//       how far the panel's frames (poses) are from panel K's, or from those of
//       method M (of the scene's kind) through the panel's keyframes (poses)
//       (analysis/comparison.hpp)
//   "discrepancy:P", "discrepancy-t:P"            arrow scenes: the largest E of
//       predictor P (previous, average, pita) over the pattern, and the time of it
//   "property:NAME"                               arrow scenes, in a claim: the value
//       `pita audit` measures for property NAME on the panel's three keyframes
//       (its deviation, or for winding-aware and knot-controlled its reaction)
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/methods.hpp"

namespace pita::scene {

enum class MeasureKind {
  discrepancy_max,
  path_length,
  turning,
  winding_range,
  overreaction,
  pop,
  handle_shift,
  ara,
  area,
  gain,
  turn,
  jump,   // "gain:K.x" ...: one keyframe parameter
  angle,  // "angle:M@t"
  scale_step,
  turn_step,
  scale_min,
  scale_max,       // the drawn frames (analysis/frame_steps.hpp)
  frame_distance,  // "frame-distance:/panels/K" or ":M": claims only (analysis/comparison.hpp)
  property,  // "property:NAME": claims only, a property of Sec. 4 on the panel's keyframes (analysis/properties.hpp)
  discrepancy_of,
  discrepancy_time,  // "discrepancy:P", "discrepancy-t:P": one predictor's largest E, and its time
  velocity_jump,     // pose scenes: the largest jump of the body's velocity (analysis/measure.hpp)
};

struct MeasureEntry {
  std::string_view name;  // "pop"; for the kinds with an argument, the prefix "gain:"
  MeasureKind kind;
  bool argument = false;  // "gain:B.q", "angle:P8@0.25"
};

// Every measure, in the order messages, the schema and docs/reference/render.md list them.
std::span<const MeasureEntry> measure_entries();

// Which scenes measure a name: `pita measure` measures arrow motions and pose
// motions differently (analysis/measure.hpp), and a name the scene's motion
// has no number for is refused rather than printed as "-". The scenes are
// named by the family of their layers, as scene::layers_of<LayerType> does:
// `Layer` for arrow scenes, `PoseLayer` for pose scenes (of the plane or of
// space); both are instantiated in measure_name.cpp.
template <class LayerType>
std::span<const MeasureEntry> measure_entries_of();

struct MeasureName {
  MeasureKind kind = MeasureKind::overreaction;
  std::string text;       // as written: "gain:B.q", "angle:P8@0.25"
  std::string parameter;  // gain, turn, jump: "B.q"; property: its name; discrepancy: the predictor
  Method method{};        // angle: the other arrow method
  // angle: another panel of the scene instead ("angle:/panels/1@0.25");
  // frame-distance: the other panel. Only a claim may name a panel (its
  // reader checks the index).
  std::optional<std::size_t> panel;
  double t = 0.0;  // angle: the time
  // frame-distance: the other method instead of a panel ("frame-distance:Alexa").
  std::optional<AnyMethod> versus;
  friend bool operator==(const MeasureName&, const MeasureName&) = default;
};

// `text` parsed for a scene whose layers are `LayerType`, or why it is
// refused (a sentence without the pointer: "unknown measure \"x\"; ...",
// "\"ara\" is measured in pose scenes only ...").
template <class LayerType>
std::variant<MeasureName, std::string> parse_measure(std::string_view text);

// The default of a layer that names none: ["overreaction", "pop"] in arrow
// scenes, ["ara", "area"] in pose scenes.
template <class LayerType>
std::vector<MeasureName> default_measures();

}  // namespace pita::scene
