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
//   "scale-max", "turn-step-t"                    pattern draws (analysis/frame_steps.hpp)
//   "frame-distance:/panels/K"                    arrow and pose scenes, in a claim:
//       how far the panel's frames (poses) are from panel K's (analysis/comparison.hpp);
//       "frame-distance:M", M a method of the scene's kind: from the frames
//       of M through the panel's keyframes or poses (appendix B, Fig. B.30;
//       SAM Fig. 4), and in arrow scenes "frame-distance:/panels/K/layers/L": from the motion that layer
//       of panel K draws (Fig. D.35's variants, each a layer)
//   "knot-distance"                               arrow scenes: how far the panel's
//       frames at its knots are from its keyframes (0 when it interpolates them)
//   "guess-distance:G", "guess-discrepancy:G"     arrow scenes, in a claim: the
//       distance and the discrepancy between the arrow G of the panel's
//       "guesses" layer and the frame at its time (Figs. 16, 18)
//       "frame-distance:/panels/K@t" at time t only
//   "carried-distance:/panels/K"                  arrow scenes, in a claim: the same,
//       panel K's frames carried onto the panel's first keyframe (analysis/comparison.hpp)
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
  turn_step_time,  // "turn-step-t": the scene time of the largest turn step
  frame_distance,  // "frame-distance:/panels/K", "frame-distance:M": claims only (analysis/comparison.hpp)
  knot_distance,   // the frames at the knots against the keyframes (analysis/comparison.hpp)
  guess_distance,
  guess_discrepancy,  // "guess-distance:G", "guess-discrepancy:G": claims only, a guess of the panel's "guesses"
  property,  // "property:NAME": claims only, a property of Sec. 4 on the panel's keyframes (analysis/properties.hpp)
  discrepancy_of,
  discrepancy_time,  // "discrepancy:P", "discrepancy-t:P": one predictor's largest E, and its time
  velocity_jump,     // pose scenes: the largest jump of the body's velocity (analysis/measure.hpp)
  carried_distance,  // "carried-distance:/panels/K": claims only, arrow scenes (analysis/comparison.hpp)
  inflections,       // the sign changes of the curvature of the path of p (analysis/measure.hpp)
};

struct MeasureEntry {
  std::string_view name;  // "pop"; for the kinds with an argument, the prefix "gain:"
  MeasureKind kind;
  bool argument = false;  // "gain:B.q", "angle:P8@0.25"
  // A distance between the frames of two drawn motions, in the scene's units
  // (arrow scenes): what a claim that it is above a bound asks a reader to
  // see, so the lint's small-feature check measures it in pixels.
  bool drawn_distance = false;
};

// Every measure, in the order messages, the schema and docs/reference/render.md list them.
std::span<const MeasureEntry> measure_entries();
// Its row's drawn_distance.
bool is_drawn_distance(MeasureKind kind);

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
  std::string parameter;  // gain, turn, jump: "B.q"; property: its name; discrepancy: the predictor;
                          // guess-distance, guess-discrepancy: the guess's name
  Method method{};        // angle: the other arrow method
  // angle: another panel of the scene instead ("angle:/panels/1@0.25");
  // frame-distance, carried-distance: the other panel. Only a claim may name a panel (its
  // reader checks the index).
  std::optional<std::size_t> panel;
  double t = 0.0;  // angle: the time
  // frame-distance: a layer of that panel instead ("/panels/1/layers/4"), the
  // motion it draws (a pattern or trajectory layer's own method or options,
  // a compare layer's method).
  std::optional<std::size_t> layer;
  // frame-distance: one time instead of the knots the panels share
  // ("frame-distance:/panels/K@t", also outside them: an extrapolation).
  std::optional<double> at;
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
