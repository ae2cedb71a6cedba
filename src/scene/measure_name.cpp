#include "scene/measure_name.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <type_traits>

#include <fmt/format.h>

#include "scene/did_you_mean.hpp"
#include "scene/json_reader.hpp"
#include "scene/layers.hpp"

namespace pita::scene {

namespace {

using detail::quoted_choices;

// The measures of arrow scenes, then those of pose scenes (plain names before
// those with an argument in each).
constexpr std::array<MeasureEntry, 28> kMeasures{{
    {"discrepancy-max", MeasureKind::discrepancy_max},
    {"path-length", MeasureKind::path_length},
    {"turning", MeasureKind::turning},
    {"inflections", MeasureKind::inflections},
    {"winding-range", MeasureKind::winding_range},
    {"overreaction", MeasureKind::overreaction},
    {"pop", MeasureKind::pop},
    {"handle-shift", MeasureKind::handle_shift},
    {"scale-step", MeasureKind::scale_step},
    {"turn-step", MeasureKind::turn_step},
    {"scale-min", MeasureKind::scale_min},
    {"scale-max", MeasureKind::scale_max},
    {"turn-step-t", MeasureKind::turn_step_time},
    {"knot-distance", MeasureKind::knot_distance},
    {"gain:", MeasureKind::gain, true},
    {"turn:", MeasureKind::turn, true},
    {"jump:", MeasureKind::jump, true},
    {"angle:", MeasureKind::angle, true},
    {"discrepancy:", MeasureKind::discrepancy_of, true},
    {"discrepancy-t:", MeasureKind::discrepancy_time, true},
    {"guess-distance:", MeasureKind::guess_distance, true, true},
    {"guess-discrepancy:", MeasureKind::guess_discrepancy, true},
    // A claim's: this panel's frames against another panel's, carried onto
    // this panel's first keyframe (analysis/comparison.hpp).
    {"carried-distance:", MeasureKind::carried_distance, true, true},
    // Both families': a claim measures a property of pita audit (or pita
    // audit poses) on the panel's three keyframes or poses, or compares the
    // frames of two panels of an arrow scene, or the poses of two panels of a
    // pose scene.
    {"property:", MeasureKind::property, true},
    {"frame-distance:", MeasureKind::frame_distance, true, true},
    {"ara", MeasureKind::ara},
    {"area", MeasureKind::area},
    {"velocity-jump", MeasureKind::velocity_jump},
}};
constexpr std::size_t kArrowMeasures = 25;     // the first ones
constexpr std::size_t kFirstPoseMeasure = 23;  // "property:", "frame-distance:", then the pose scenes' own

// What depends on the scene's family of layers: its measures, how messages
// name its scenes, the other family, and what a layer that names none shows.
template <class LayerType>
struct MeasureFamily;

template <>
struct MeasureFamily<Layer> {
  static constexpr std::span<const MeasureEntry> entries{kMeasures.data(), kArrowMeasures};
  static constexpr std::string_view words = "arrow (keyframe) scenes";
  using Other = PoseLayer;
  static constexpr std::array<std::string_view, 2> defaults = {"overreaction", "pop"};
  // What else arrow scenes measure, for the message of an unknown name.
  static constexpr std::string_view more =
      ", or \"gain:K.x\", \"turn:K.x\" and \"jump:K.x\" with K a keyframe (A, B, ...) and x one of p, q, "
      "p.x, p.y, q.x, q.y, m, w, t, or \"angle:M@t\" with M an arrow method (in a claim also another "
      "panel, \"/panels/1\") and t a time, \"discrepancy:P\" and \"discrepancy-t:P\" with P a predictor "
      "(previous, average, pita), or in a claim \"frame-distance:/panels/K\" (or at one time, "
      "\"frame-distance:/panels/K@t\", or \"frame-distance:/panels/K/layers/L\", the motion that layer draws, or "
      "\"frame-distance:M\", M a method of arrow scenes), \"carried-distance:/panels/K\", \"guess-distance:G\" and "
      "\"guess-discrepancy:G\" (G a guess of the panel's \"guesses\" layer) and \"property:NAME\" (a property of "
      "Sec. 4, as pita audit names it)";
};

template <>
struct MeasureFamily<PoseLayer> {
  static constexpr std::span<const MeasureEntry> entries{kMeasures.data() + kFirstPoseMeasure,
                                                         kMeasures.size() - kFirstPoseMeasure};
  static constexpr std::string_view words = "pose scenes";
  using Other = Layer;
  static constexpr std::array<std::string_view, 2> defaults = {"ara", "area"};
  static constexpr std::string_view more =
      ", or in a claim \"frame-distance:/panels/K\" (or \"frame-distance:M\", M a pose method) and \"property:NAME\" "
      "(a property as pita audit poses names it)";
};

// The predictors of Sec. 6.1 (analysis::DiscrepancyStats::predictor).
constexpr std::array<std::string_view, 3> kPredictors = {"previous", "average", "pita"};

// "angle:/panels/1@0.25": the other panel of a claim's angle.
constexpr std::string_view kPanelsPrefix = "/panels/";

// "/panels/1/layers/4": a layer of another panel, in "frame-distance:".
constexpr std::string_view kLayersInfix = "/layers/";

// "0.25" -> 0.25; nullopt for anything but a whole finite number.
std::optional<double> finite_number(std::string_view text) {
  double t = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), t);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(t)) {
    return std::nullopt;
  }
  return t;
}

// "/panels/3" -> 3; nullopt for anything else.
std::optional<std::size_t> panel_index(std::string_view pointer) {
  if (!pointer.starts_with(kPanelsPrefix)) return std::nullopt;
  const std::string_view index = pointer.substr(kPanelsPrefix.size());
  std::size_t k = 0;
  const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), k);
  if (index.empty() || error != std::errc() || end != index.data() + index.size()) return std::nullopt;
  return k;
}

// "frame-distance:" and `rest`, "/panels/K", "/panels/K/layers/L" or an
// arrow method, into `measure`; why not otherwise.
template <class LayerType>
std::optional<std::string> parse_frame_distance(std::string_view text, std::string_view rest, MeasureName& measure) {
  // "/panels/K@t": the two panels at one time only.
  if (const std::size_t at = rest.starts_with(kPanelsPrefix) ? rest.find('@') : std::string_view::npos;
      at != std::string_view::npos) {
    const std::optional<double> t = finite_number(rest.substr(at + 1));
    if (!t) {
      return fmt::format("in \"{}\": the time after \"@\" must be a finite number (got \"{}\")", text,
                         rest.substr(at + 1));
    }
    measure.at = t;
    rest = rest.substr(0, at);
    if (rest.find(kLayersInfix) != std::string_view::npos) {
      return fmt::format("in \"{}\": \"@t\" compares two panels (\"frame-distance:/panels/K@t\"), not a layer", text);
    }
  }
  const std::size_t layers = rest.starts_with(kPanelsPrefix) ? rest.find(kLayersInfix) : std::string_view::npos;
  const std::optional<std::size_t> panel = panel_index(rest.substr(0, layers));
  if (panel && layers != std::string_view::npos) {
    std::size_t layer = 0;
    const std::string_view index = rest.substr(layers + kLayersInfix.size());
    const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), layer);
    if (index.empty() || error != std::errc() || end != index.data() + index.size()) {
      return fmt::format("\"{}\" must be \"frame-distance:/panels/K/layers/L\", L a layer's index", text);
    }
    measure.layer = layer;
  }
  // Another panel, or another method of the scene's kind.
  using MethodOfScene = std::conditional_t<std::is_same_v<LayerType, Layer>, Method, PoseMethod>;
  const MethodOfScene* named = rest.starts_with(kPanelsPrefix) ? nullptr : find_method_of<MethodOfScene>(rest);
  if (!panel && named == nullptr) {
    return fmt::format(
        "\"{}\" must be \"frame-distance:/panels/K\", K a panel's index, or \"frame-distance:M\", M a method of {}",
        text, MeasureFamily<LayerType>::words);
  }
  measure.panel = panel;
  if (named != nullptr) measure.versus = AnyMethod(*named);
  return std::nullopt;
}

constexpr std::array<std::string_view, 9> kParameters = {"p", "q", "p.x", "p.y", "q.x", "q.y", "m", "w", "t"};

// "B.q", "K27.p.x": a keyframe (A..Z, or K and a number) and a parameter.
bool is_keyframe_parameter(std::string_view rest) {
  std::size_t key = 0;
  if (rest.size() > 1 && rest[0] == 'K' && rest[1] >= '0' && rest[1] <= '9') {
    key = 1;
    while (key < rest.size() && rest[key] >= '0' && rest[key] <= '9') ++key;
  } else if (!rest.empty() && rest[0] >= 'A' && rest[0] <= 'Z') {
    key = 1;
  }
  if (key == 0 || key >= rest.size() || rest[key] != '.') return false;
  rest.remove_prefix(key + 1);
  for (const std::string_view parameter : kParameters) {
    if (rest == parameter) return true;
  }
  return false;
}

// The names a scene of the family may show, for messages: "pop", ...
// (without "gain:K.x", "angle:M@t", ...).
template <class LayerType>
std::vector<std::string_view> names_of() {
  std::vector<std::string_view> names;
  for (const MeasureEntry& entry : MeasureFamily<LayerType>::entries) {
    if (!entry.argument) names.push_back(entry.name);
  }
  return names;
}

template <class LayerType>
std::string unknown(std::string_view text) {
  using Family = MeasureFamily<LayerType>;
  const std::vector<std::string_view> names = names_of<LayerType>();
  const std::vector<std::string> close = closest_names(text, names);
  if (!close.empty()) return fmt::format("unknown measure \"{}\"{}", text, did_you_mean(close));
  return fmt::format("unknown measure \"{}\"; {} measure {}{}", text, Family::words, quoted_choices(names),
                     Family::more);
}

}  // namespace

std::span<const MeasureEntry> measure_entries() { return kMeasures; }

bool is_drawn_distance(MeasureKind kind) {
  return std::ranges::any_of(kMeasures, [&](const MeasureEntry& e) { return e.kind == kind && e.drawn_distance; });
}

template <class LayerType>
std::span<const MeasureEntry> measure_entries_of() {
  return MeasureFamily<LayerType>::entries;
}

template <class LayerType>
std::variant<MeasureName, std::string> parse_measure(std::string_view text) {
  const MeasureEntry* found = nullptr;
  for (const MeasureEntry& entry : kMeasures) {
    if (entry.argument ? text.starts_with(entry.name) : text == entry.name) found = &entry;
  }
  if (found == nullptr) return unknown<LayerType>(text);
  MeasureName measure{found->kind, std::string(text), {},           {},          std::nullopt,
                      0.0,         std::nullopt,      std::nullopt, std::nullopt};
  const std::string_view rest = text.substr(found->argument ? found->name.size() : text.size());
  if (found->kind == MeasureKind::gain || found->kind == MeasureKind::turn || found->kind == MeasureKind::jump) {
    if (!is_keyframe_parameter(rest)) {
      return fmt::format(
          "\"{}\" must name a keyframe and a parameter, \"{}K.x\" with K a keyframe (A, B, ...) "
          "and x one of p, q, p.x, p.y, q.x, q.y, m, w, t",
          text, found->name);
    }
    measure.parameter = std::string(rest);
  } else if (found->kind == MeasureKind::property) {
    // The name is checked against the properties when measured (analysis/properties.hpp).
    if (rest.empty() || rest.find_first_not_of("abcdefghijklmnopqrstuvwxyz-") != std::string_view::npos) {
      return fmt::format(
          "\"{}\" must be \"property:NAME\", NAME a property of Sec. 4 as `pita audit` names it "
          "(\"locally-perseverant\", \"handle-invariant\", ...)",
          text);
    }
    measure.parameter = std::string(rest);
  } else if (found->kind == MeasureKind::discrepancy_of || found->kind == MeasureKind::discrepancy_time) {
    if (std::find(kPredictors.begin(), kPredictors.end(), rest) == kPredictors.end()) {
      return fmt::format("\"{}\" must be \"{}P\", P a predictor of Sec. 6.1: {}", text, found->name,
                         quoted_choices(kPredictors));
    }
    measure.parameter = std::string(rest);
  } else if (found->kind == MeasureKind::guess_distance || found->kind == MeasureKind::guess_discrepancy) {
    // The name is looked up in the panel's "guesses" layers when measured.
    if (rest.empty()) return fmt::format("\"{}\" must be \"{}G\", G the name of a guess", text, found->name);
    measure.parameter = std::string(rest);
  } else if (found->kind == MeasureKind::frame_distance) {
    if (std::optional<std::string> refused = parse_frame_distance<LayerType>(text, rest, measure)) return *refused;
  } else if (found->kind == MeasureKind::carried_distance) {
    const std::optional<std::size_t> panel = panel_index(rest);
    if (!panel) return fmt::format("\"{}\" must be \"{}/panels/K\", K a panel's index", text, found->name);
    measure.panel = panel;
  } else if (found->kind == MeasureKind::angle) {
    const std::size_t at = rest.find('@');
    const std::string_view method = rest.substr(0, at);
    if (at == std::string_view::npos || method.empty()) {
      return fmt::format("\"{}\" must be \"angle:M@t\", an arrow method M and a time t", text);
    }
    const Method* named = nullptr;
    if (method.starts_with(kPanelsPrefix)) {
      measure.panel = panel_index(method);
      if (!measure.panel) {
        return fmt::format("in \"{}\": \"{}\" must be \"/panels/\" and a panel's index", text, method);
      }
    } else if ((named = find_method_of<Method>(method)) == nullptr) {
      return fmt::format("in \"{}\": {}", text, pita::unknown_method_reason(method, is_method_of<Method>));
    }
    const std::string_view time = rest.substr(at + 1);
    const std::optional<double> t = finite_number(time);
    if (!t) return fmt::format("in \"{}\": the time after \"@\" must be a finite number (got \"{}\")", text, time);
    if (named != nullptr) measure.method = *named;
    measure.t = *t;
  }
  const std::span<const MeasureEntry> own = MeasureFamily<LayerType>::entries;
  if (found < own.data() || found >= own.data() + own.size()) {
    return fmt::format("\"{}\" is measured in {} only; {} measure {}", text,
                       MeasureFamily<typename MeasureFamily<LayerType>::Other>::words, MeasureFamily<LayerType>::words,
                       quoted_choices(names_of<LayerType>()));
  }
  return measure;
}

template <class LayerType>
std::vector<MeasureName> default_measures() {
  std::vector<MeasureName> out;
  for (const std::string_view name : MeasureFamily<LayerType>::defaults) {
    out.push_back(std::get<MeasureName>(parse_measure<LayerType>(name)));
  }
  return out;
}

template std::span<const MeasureEntry> measure_entries_of<Layer>();
template std::span<const MeasureEntry> measure_entries_of<PoseLayer>();
template std::variant<MeasureName, std::string> parse_measure<Layer>(std::string_view);
template std::variant<MeasureName, std::string> parse_measure<PoseLayer>(std::string_view);
template std::vector<MeasureName> default_measures<Layer>();
template std::vector<MeasureName> default_measures<PoseLayer>();

}  // namespace pita::scene
