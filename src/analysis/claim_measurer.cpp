#include "analysis/claim_measurer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/comparison.hpp"
#include "analysis/frame_steps.hpp"
#include "analysis/pose_properties.hpp"
#include "analysis/properties.hpp"
#include "core/overloaded.hpp"
#include "core/pose_traits.hpp"
#include "motion/sampler.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/limits.hpp"

namespace pita::analysis {

namespace {

using scene::MeasureKind;

[[noreturn]] void unmeasured(const motion::Stage& stage, const std::string& pointer, std::size_t panel,
                             const scene::MeasureName& measure, std::string_view why) {
  throw scene::SceneError(stage.scene().path, pointer,
                          fmt::format("{} has no \"{}\": {}", panel_name(stage, panel), measure.text, why));
}

// "property:NAME": what `pita audit` measures for the property on the
// panel's three keyframes (its probe, seed 1), with the panel's method; in a
// pose scene what `pita audit poses` measures on its three poses.
double property_value(const motion::Stage& stage, std::size_t panel, const scene::MeasureName& measure,
                      const std::string& pointer) {
  const auto unknown = [&](const auto& all) {
    std::vector<std::string_view> names;
    for (const auto& p : all) names.push_back(p.id);
    throw scene::SceneError(
        stage.scene().path, pointer,
        fmt::format("unknown property \"{}\"{}; the properties are {}", measure.parameter,
                    scene::did_you_mean(scene::closest_names(measure.parameter, names)), fmt::join(names, ", ")));
  };
  const auto arrows = [&](const scene::KeyframeKeys& keys) {
    const PropertyInfo* property = find_property(measure.parameter);
    if (property == nullptr) unknown(all_properties());
    if (keys.keyframes.size() != 3 || info(keys.method).keyframe_count != 3) {
      unmeasured(stage, pointer, panel, measure,
                 "the properties of Sec. 4 are measured on three keyframes and a method "
                 "through three");
    }
    const KeyframeTriple triple{keys.keyframes[0], keys.keyframes[1], keys.keyframes[2]};
    return probe(property->property, keys.method, triple, 1).value;
  };
  const auto poses = [&]<class Pose>(const scene::PoseKeys<Pose>& keys) {
    const PosePropertyInfo* property = find_pose_property(measure.parameter);
    if (property == nullptr) unknown(all_pose_properties());
    if (keys.poses.size() != 3) {
      unmeasured(stage, pointer, panel, measure, "the properties of pita audit poses are measured on three poses");
    }
    const PoseTriple<Pose> triple{keys.poses[0], keys.poses[1], keys.poses[2]};
    return probe_pose(property->property, keys.method, triple, 1).value;
  };
  return std::visit(overloaded{[&](const scene::KeyframeKeys& keys) { return arrows(keys); },
                               [&](const scene::PointKeys&) -> double {
                                 unmeasured(stage, pointer, panel, measure,
                                            "the properties of Sec. 4 are measured on three keyframes");
                               },
                               [&](const scene::PlanePoseKeys& keys) { return poses(keys); },
                               [&](const scene::SpacePoseKeys& keys) { return poses(keys); }},
                    stage.panel(panel).keys);
}

// The options of the panel's method (those a layer's own options patch).
MethodOptions own_options(const motion::Stage& stage, std::size_t panel) {
  return scene::track_method(stage.panel(panel).keys)->options;
}

// The motion that layer `layer` of the panel draws (its own layers, else
// the scene's): a pattern or trajectory layer's own method and options over
// the panel's (N57), a compare layer's method; a SceneError for a layer that
// draws no motion of its own.
motion::SceneMotion drawn_motion(const motion::Stage& stage, std::size_t panel, std::size_t layer,
                                 const scene::MeasureName& measure, const std::string& pointer) {
  const scene::Panel& own = stage.panel(panel);
  const scene::LayersOf<scene::Layer> layers = scene::layers_of<scene::Layer>(stage.scene(), own);
  if (layer >= layers.layers.size()) {
    unmeasured(stage, pointer, panel, measure,
               fmt::format("it has no layer {} (it draws {} layers)", layer, layers.layers.size()));
  }
  const auto of = [&](std::optional<Method> method, const scene::MethodOptionsPatch& options) {
    return motion::with_layer_method(stage.scene(), own, method, options.over(own_options(stage, panel)));
  };
  return std::visit(
      overloaded{[&](const scene::PatternLayer& l) { return of(l.method, l.options); },
                 [&](const scene::TrajectoryLayer& l) { return of(l.method, l.options); },
                 [&](const scene::CompareLayer& l) { return motion::with_method(stage.scene(), own, l.method); },
                 [&](const auto&) -> motion::SceneMotion {
                   unmeasured(stage, pointer, panel, measure,
                              fmt::format("its layer {} draws no motion of its own (a \"pattern\", \"trajectory\" "
                                          "or \"compare\" layer does)",
                                          layers.pointer(layer)));
                 }},
      layers.layers[layer]);
}

// The guess named measure.parameter of the panel's "guesses" layers (its
// own layers, else the scene's), or a SceneError naming those it has.
const scene::Guess& guess_named(const motion::Stage& stage, std::size_t panel, const scene::MeasureName& measure,
                                const std::string& pointer) {
  std::vector<std::string_view> names;
  for (const scene::Layer& layer : scene::layers_of<scene::Layer>(stage.scene(), stage.panel(panel)).layers) {
    const auto* guesses = std::get_if<scene::GuessesLayer>(&layer);
    if (guesses == nullptr) continue;
    for (const scene::Guess& guess : guesses->guesses) {
      if (guess.name == measure.parameter) return guess;
      names.push_back(guess.name);
    }
  }
  if (names.empty()) unmeasured(stage, pointer, panel, measure, "the panel has no \"guesses\" layer");
  unmeasured(stage, pointer, panel, measure, fmt::format("its guesses are named {}", fmt::join(names, ", ")));
}

}  // namespace

std::string panel_name(const motion::Stage& stage, std::size_t index) {
  const scene::Panel& panel = stage.panel(index);
  const std::string what = panel.title.empty() ? scene::method_id(panel.keys) : panel.title;
  return panel.pointer.empty() ? fmt::format("the scene ({})", what) : fmt::format("panel {} ({})", index, what);
}

Measurer::Measurer(const motion::Stage& stage) : stage_(&stage), measures_(stage.size()), steps_(stage.size()) {}

const MotionMeasures& Measurer::measures(std::size_t panel) {
  std::optional<MotionMeasures>& kept = measures_.at(panel);
  if (!kept) kept = measure_panel(*stage_, panel);
  if (kept->no_motion) (void)stage_->motion(panel);  // throws its NoMotion
  return *kept;
}

namespace {

// "points", "poses of the plane", ...: what a panel that is not of keyframes
// has instead, for the refusal of a measure of keyframes.
std::string_view what_the_panel_has(const scene::MotionKeys& keys) {
  return std::visit(overloaded{[](const scene::KeyframeKeys&) { return std::string_view("keyframes"); },
                               [](const scene::PointKeys&) { return std::string_view("points"); },
                               [](const scene::PlanePoseKeys&) { return PoseTraits<Affine2>::noun; },
                               [](const scene::SpacePoseKeys&) { return PoseTraits<Affine3>::noun; }},
                    keys);
}

}  // namespace

void Measurer::need_keyframes(std::size_t panel, const scene::MeasureName& measure, const std::string& pointer,
                              std::optional<std::size_t> other) const {
  const motion::Stage& stage = *stage_;
  (void)stage.motion(panel);  // its NoMotion first
  const scene::MotionKeys& keys = stage.panel(panel).keys;
  if (!std::holds_alternative<scene::KeyframeKeys>(keys)) {
    unmeasured(stage, pointer, panel, measure,
               fmt::format("it is measured on keyframes, and the panel has {}", what_the_panel_has(keys)));
  }
  if (other && !std::holds_alternative<scene::KeyframeKeys>(stage.panel(*other).keys)) {
    unmeasured(stage, pointer, panel, measure, "the other panel has no keyframes");
  }
}

Source source_of(MeasureKind kind) {
  switch (kind) {
    case MeasureKind::discrepancy_max:
    case MeasureKind::discrepancy_of:
    case MeasureKind::discrepancy_time:
    case MeasureKind::path_length:
    case MeasureKind::turning:
    case MeasureKind::inflections:
    case MeasureKind::winding_range:
    case MeasureKind::overreaction:
    case MeasureKind::pop:
    case MeasureKind::ara:
    case MeasureKind::velocity_jump:
    case MeasureKind::area:
    case MeasureKind::gain:
    case MeasureKind::turn:
    case MeasureKind::jump:
      return Source::measures;
    case MeasureKind::scale_step:
    case MeasureKind::turn_step:
    case MeasureKind::scale_min:
    case MeasureKind::scale_max:
    case MeasureKind::turn_step_time:
      return Source::frame_steps;
    case MeasureKind::angle:
    case MeasureKind::frame_distance:
    case MeasureKind::carried_distance:
    case MeasureKind::handle_shift:
    case MeasureKind::knot_distance:
    case MeasureKind::guess_distance:
    case MeasureKind::guess_discrepancy:
      return Source::comparison;
    case MeasureKind::property:
      return Source::property;
  }
  return Source::measures;  // unreachable: every kind is listed
}

double Measurer::value(std::size_t panel, const scene::MeasureName& measure, const std::string& pointer,
                       std::optional<std::size_t> layer) {
  const motion::Stage& stage = *stage_;
  switch (source_of(measure.kind)) {
    case Source::measures:
      return measured_value(panel, measure, pointer);
    case Source::frame_steps: {  // the drawn frames
      need_keyframes(panel, measure, pointer);
      std::optional<FrameSteps>& kept = steps_.at(panel);
      if (!kept) kept = frame_steps(stage, panel);
      return *frame_step(*kept, measure.kind);
    }
    case Source::comparison:  // with another panel (angle, frame-distance), method or drawn arrow
      // frame-distance compares poses too: a pose scene's panels are all of its kind.
      if (measure.kind == MeasureKind::frame_distance &&
          (std::holds_alternative<scene::PlanePoseKeys>(stage.panel(panel).keys) ||
           std::holds_alternative<scene::SpacePoseKeys>(stage.panel(panel).keys))) {
        if (layer || measure.layer) {
          unmeasured(stage, pointer, panel, measure, "a layer's motion is compared in arrow scenes");
        }
        return measure.versus ? method_distance(stage, panel, *measure.versus)
                              : frame_distance(stage, panel, *measure.panel, measure.at);
      }
      need_keyframes(panel, measure, pointer, measure.panel);
      if (measure.kind == MeasureKind::frame_distance && (layer || measure.layer)) {
        // "/panels/K/layers/L", or the claim's "layer": the motion a layer draws.
        std::optional<motion::SceneMotion> drawn_mine, drawn_theirs;
        const std::size_t other = measure.panel.value_or(panel);
        const motion::SceneMotion& mine =
            layer ? drawn_mine.emplace(drawn_motion(stage, panel, *layer, measure, pointer)) : stage.motion(panel);
        const motion::SceneMotion& theirs =
            measure.layer ? drawn_theirs.emplace(drawn_motion(stage, other, *measure.layer, measure, pointer))
                          : stage.motion(other);
        return frame_distance(mine, theirs);
      }
      if (measure.kind == MeasureKind::frame_distance) {
        return measure.versus ? method_distance(stage, panel, *measure.versus)
                              : frame_distance(stage, panel, *measure.panel, measure.at);
      }
      if (measure.kind == MeasureKind::carried_distance) return carried_distance(stage, panel, *measure.panel);
      if (measure.kind == MeasureKind::angle) {
        if (measure.panel) return panel_angle(stage, panel, *measure.panel, measure.t);
        return vector_angle(stage, panel, measure.method, measure.t);
      }
      if (measure.kind == MeasureKind::knot_distance) return knot_distance(stage, panel);
      if (measure.kind == MeasureKind::guess_distance || measure.kind == MeasureKind::guess_discrepancy) {
        return guess_gap(stage, panel, guess_named(stage, panel, measure, pointer),
                         measure.kind == MeasureKind::guess_discrepancy);
      }
      if (scene::figure_of<scene::KeyframeKeys>(stage.panel(panel)).shapes.empty()) {
        unmeasured(stage, pointer, panel, measure, "the panel has no shapes");
      }
      return handle_shift(stage, panel);
    case Source::property:
      (void)stage.motion(panel);  // its NoMotion first
      return property_value(stage, panel, measure, pointer);
  }
  unmeasured(stage, pointer, panel, measure, "not a measure of a claim");
}

namespace {

// Why a panel's measures lack the number `kind` reads.
std::string_view why_unmeasured(MeasureKind kind) {
  switch (kind) {
    case MeasureKind::discrepancy_max:
      return "no frame of its pattern has a prediction";
    case MeasureKind::discrepancy_of:
    case MeasureKind::discrepancy_time:
      return "no frame of its pattern has this prediction";
    case MeasureKind::path_length:
    case MeasureKind::turning:
    case MeasureKind::inflections:
      return "its motion has no path";
    case MeasureKind::winding_range:
      return "its frames have no winding";
    case MeasureKind::overreaction:
      return "no keyframe parameter was tweaked";
    case MeasureKind::pop:
      return "pops are measured on keyframes";
    case MeasureKind::ara:
      return "ARA is measured on poses";
    case MeasureKind::velocity_jump:
      return "velocity jumps are measured on poses";
    case MeasureKind::area:
      return "the area is measured on poses";
    case MeasureKind::gain:
    case MeasureKind::turn:
    case MeasureKind::jump:
      return "no keyframe has that parameter";
    case MeasureKind::scale_step:  // computed from the panel itself by value()
    case MeasureKind::turn_step:
    case MeasureKind::scale_min:
    case MeasureKind::scale_max:
    case MeasureKind::turn_step_time:
    case MeasureKind::angle:
    case MeasureKind::frame_distance:
    case MeasureKind::carried_distance:
    case MeasureKind::handle_shift:
    case MeasureKind::knot_distance:
    case MeasureKind::guess_distance:
    case MeasureKind::guess_discrepancy:
    case MeasureKind::property:
      break;
  }
  return "not a measure of a claim";
}

// The largest gain, turn or jump of the parameters named `measure.parameter` or under it.
std::optional<double> largest_reaction(const ArrowMeasures& m, const scene::MeasureName& measure) {
  std::optional<double> largest;
  for (const ParameterReaction& p : m.parameters) {
    if (p.name != measure.parameter && !p.name.starts_with(measure.parameter + ".")) continue;
    const double x = measure.kind == MeasureKind::gain ? p.gain : measure.kind == MeasureKind::turn ? p.turn : p.jump;
    largest = std::max(largest.value_or(-1.0), x);
  }
  return largest;
}

// The largest E over the predictors, or of one predictor (or the time of it).
std::optional<double> largest_discrepancy(const ArrowMeasures& m, const scene::MeasureName& measure) {
  std::optional<double> largest;
  for (const DiscrepancyStats& d : m.discrepancy) {
    if (d.frames == 0) continue;
    if (measure.kind == MeasureKind::discrepancy_max) {
      largest = std::max(largest.value_or(-1.0), d.max);
    } else if (d.predictor == measure.parameter) {
      return measure.kind == MeasureKind::discrepancy_of ? d.max : d.t_of_max;
    }
  }
  return largest;
}

// The number a claim reads from each kind's measures; nullopt when the kind
// lacks it (why_unmeasured says why).
std::optional<double> claimed_number(const ArrowMeasures& m, const scene::MeasureName& measure) {
  const MeasureKind kind = measure.kind;
  if (kind == MeasureKind::discrepancy_max || kind == MeasureKind::discrepancy_of ||
      kind == MeasureKind::discrepancy_time) {
    return largest_discrepancy(m, measure);
  }
  if (kind == MeasureKind::path_length) return m.path_p.length;
  if (kind == MeasureKind::turning) return m.path_p.turning;
  if (kind == MeasureKind::inflections) return m.path_p.inflections;
  if (kind == MeasureKind::winding_range) return m.winding_max - m.winding_min;
  if (kind == MeasureKind::overreaction && m.most_sensitive >= 0) {
    return m.parameters[static_cast<std::size_t>(m.most_sensitive)].gain;
  }
  if (kind == MeasureKind::pop) return m.pops ? 1.0 : 0.0;
  if (kind == MeasureKind::gain || kind == MeasureKind::turn || kind == MeasureKind::jump) {
    return largest_reaction(m, measure);
  }
  return std::nullopt;  // a measure of poses, or one value() computes from the panel
}

std::optional<double> claimed_number(const PointMeasures& m, const scene::MeasureName& measure) {
  if (measure.kind == MeasureKind::path_length) return m.path.length;
  if (measure.kind == MeasureKind::turning) return m.path.turning;
  if (measure.kind == MeasureKind::inflections) return m.path.inflections;
  return std::nullopt;
}

template <class Pose>
std::optional<double> claimed_number(const PoseMeasures<Pose>& m, const scene::MeasureName& measure) {
  if (measure.kind == MeasureKind::ara) return m.ara;
  if (measure.kind == MeasureKind::velocity_jump) return m.velocity_jump;
  if (measure.kind == MeasureKind::area) return m.area.excursion;
  return std::nullopt;
}

}  // namespace

double Measurer::measured_value(std::size_t panel, const scene::MeasureName& measure, const std::string& pointer) {
  const MotionMeasures& m = measures(panel);
  const std::optional<double> x =
      std::visit([&](const auto& measured) { return claimed_number(measured, measure); }, m.measured);
  if (!x) unmeasured(*stage_, pointer, panel, measure, why_unmeasured(measure.kind));
  return *x;
}

}  // namespace pita::analysis
