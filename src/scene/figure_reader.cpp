#include "scene/figure_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>

#include <fmt/format.h>

#include "core/methods.hpp"
#include "scene/color.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/layer_kinds.hpp"
#include "scene/pose_reader.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 8> kCanvasFields = {"width",  "height", "background", "view",
                                                           "margin", "y_axis", "columns",    "font"};

constexpr std::array<std::string_view, 2> kYAxisNames = {"up", "down"};
constexpr std::array<bool, 2> kYUp = {true, false};

template <typename LayerType>
std::vector<std::string_view> type_names(std::span<const LayerKind<LayerType>> kinds) {
  std::vector<std::string_view> names;
  for (const auto& kind : kinds) names.push_back(kind.type);
  return names;
}

// Reads a layer of one of `kinds`; `others` are the kinds of the other kind
// of scene, named in the message when a layer of theirs is used here.
template <typename LayerType, typename OtherType>
LayerType read_layer_of(const JsonReader& reader, const Json& value, const std::string& pointer,
                        std::span<const LayerKind<LayerType>> kinds, std::span<const LayerKind<OtherType>> others,
                        std::string_view scene_kind) {
  reader.object(value, pointer, "a layer");
  const Fields fields(reader, value, pointer);
  const std::vector<std::string_view> names = type_names(kinds);
  const Json& type_value = fields.required("type", "the layer type: " + quoted_choices(names));
  const std::string type_pointer = fields.at("type");
  if (!type_value.is_string()) {
    reader.fail(type_pointer, "must be " + quoted_choices(names) + " (got " + value_text(type_value) + ")");
  }
  const std::string name = type_value.get<std::string>();
  const auto found = std::find_if(kinds.begin(), kinds.end(), [&](const auto& kind) { return kind.type == name; });
  if (found == kinds.end()) {
    const bool other = std::any_of(others.begin(), others.end(), [&](const auto& kind) { return kind.type == name; });
    std::string reason;
    if (other) {
      reason = fmt::format("layer type \"{}\" {}; {} layers: {}", name,
                           scene_kind.empty() ? "draws poses (pose scenes)" : "draws arrows (keyframe scenes)",
                           scene_kind.empty() ? "this scene's" : "a pose scene's", joined(names));
    } else {
      const std::vector<std::string> suggestions = closest_names(name, names);
      reason = fmt::format("unknown layer type \"{}\"{}", name, scene_kind);
      reason += suggestions.empty() ? "; layer types: " + joined(names) : did_you_mean(suggestions);
    }
    reader.fail(type_pointer, reason);
  }
  // A field that another layer kind takes says so; any other gets a "did you
  // mean" among the fields of this kind.
  const std::span<const std::string_view> known = found->fields;
  for (const auto& [key, member] : value.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    // (key captured by name: clang before 16 cannot capture a structured binding)
    const bool elsewhere = std::any_of(kinds.begin(), kinds.end(), [&key = key](const auto& kind) {
      return std::find(kind.fields.begin(), kind.fields.end(), key) != kind.fields.end();
    });
    if (!elsewhere) break;  // check_fields below reports it
    reader.fail(fields.at(key), fmt::format("field \"{}\" is not used by a \"{}\" layer (its fields: {})", key,
                                            found->type, joined(known)));
  }
  reader.check_fields(value, pointer, known);
  return found->read(fields);
}

// "view": "auto", "shared" or {"min": [x, y], "max": [x, y]}.
void read_view(const JsonReader& reader, const Json& value, const std::string& pointer, Canvas& canvas) {
  if (value.is_string() && value.get<std::string>() == "auto") {
    canvas.view.reset();
    canvas.shared_fit = false;
    return;
  }
  if (value.is_string() && value.get<std::string>() == "shared") {
    canvas.view.reset();
    canvas.shared_fit = true;
    return;
  }
  if (!value.is_object()) {
    reader.fail(pointer,
                "must be \"auto\", \"shared\" or a box {\"min\": [x, y], \"max\": [x, y]} "
                "(got " +
                    value_text(value) + ")");
  }
  reader.check_fields(value, pointer, kBoxFields);
  canvas.view = read_box(Fields(reader, value, pointer));
  canvas.shared_fit = false;
}

// "layers": an array of at most kMaxLayers layers, each read by `read_one`.
template <typename LayerType, typename ReadOne>
std::vector<LayerType> read_layer_array(const JsonReader& reader, const Json& value, const std::string& pointer,
                                        ReadOne read_one) {
  if (!value.is_array()) {
    reader.fail(pointer, "must be an array of layers (got " + value_text(value) + ")");
  }
  if (value.size() > static_cast<std::size_t>(kMaxLayers)) {
    reader.fail(pointer, fmt::format("must have at most {} layers (got {})", kMaxLayers, value.size()));
  }
  std::vector<LayerType> layers;
  for (std::size_t i = 0; i < value.size(); ++i) {
    layers.push_back(read_one(reader, value[i], element_pointer(pointer, i)));
  }
  return layers;
}

Layer read_layer(const JsonReader& reader, const Json& value, const std::string& pointer) {
  return read_layer_of(reader, value, pointer, arrow_layer_table(), pose_layer_table(), "");
}

PoseLayer read_pose_layer(const JsonReader& reader, const Json& value, const std::string& pointer) {
  return read_layer_of(reader, value, pointer, pose_layer_table(), arrow_layer_table(), " for a pose scene");
}

}  // namespace

template <typename LayerType>
std::vector<LayerKindInfo> kind_infos(std::span<const LayerKind<LayerType>> kinds) {
  std::vector<LayerKindInfo> infos;
  for (const auto& kind : kinds) infos.push_back({kind.type, kind.fields, kind.alternative, kind.in_space, kind.draws});
  return infos;
}
std::vector<LayerKindInfo> arrow_layer_kinds() { return kind_infos(arrow_layer_table()); }
std::vector<LayerKindInfo> pose_layer_kinds() { return kind_infos(pose_layer_table()); }

}  // namespace pita::scene::detail

namespace pita::scene {

std::string_view layer_type(const Layer& layer) { return detail::kind_of(detail::arrow_layer_table(), layer).type; }
std::string_view layer_type(const PoseLayer& layer) { return detail::kind_of(detail::pose_layer_table(), layer).type; }

}  // namespace pita::scene

namespace pita::scene::detail {

std::vector<PoseLayer> read_pose_layers(const JsonReader& reader, const Json& value, const std::string& pointer) {
  return read_layer_array<PoseLayer>(reader, value, pointer, read_pose_layer);
}

std::vector<PoseLayer> read_space_pose_layers(const JsonReader& reader, const Json& value, const std::string& pointer) {
  std::vector<PoseLayer> layers = read_pose_layers(reader, value, pointer);
  std::vector<std::string_view> space;
  const std::span<const LayerKind<PoseLayer>> kinds = pose_layer_table();
  for (const auto& kind : kinds) {
    if (kind.in_space) space.push_back(kind.type);
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string type = value[i].at("type").get<std::string>();
    const auto kind = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.type == type; });
    if (kind != kinds.end() && !kind->in_space) {
      reader.fail(element_pointer(pointer, i) + "/type",
                  fmt::format("layer type \"{}\" draws pose scenes of the plane only; a 3D scene's layers: {}", type,
                              joined(space)));
    }
  }
  return layers;
}

Canvas read_canvas(const JsonReader& reader, const Json& value, const std::string& pointer) {
  reader.object(value, pointer, "the canvas");
  reader.check_fields(value, pointer, kCanvasFields);
  const Fields fields(reader, value, pointer);
  Canvas canvas;
  fields.integer("width", kMinCanvasSide, kMaxCanvasSide, canvas.width);
  fields.integer("height", kMinCanvasSide, kMaxCanvasSide, canvas.height);
  if (const Json* background = fields.get("background")) {
    const std::string at = fields.at("background");
    if (background->is_string() && background->get<std::string>() == "none") {
      canvas.background.reset();
    } else {
      const std::array<std::string_view, 1> none = {"none"};
      if (background->is_string() && !closest_names(background->get<std::string>(), none).empty()) {
        try {
          parse_color(background->get<std::string>());
        } catch (const std::invalid_argument&) {
          reader.fail(at, fmt::format("unknown color \"{}\"; did you mean \"none\" (transparent)?",
                                      background->get<std::string>()));
        }
      }
      canvas.background = reader.color(*background, at);
    }
  }
  if (const Json* view = fields.get("view")) read_view(reader, *view, fields.at("view"), canvas);
  fields.number("margin", kFraction, canvas.margin);
  fields.choice("y_axis", kYAxisNames, kYUp, canvas.y_up);
  fields.integer("columns", 1, kMaxColumns, canvas.columns);
  fields.text("font", kUnbounded, canvas.font);
  return canvas;
}

std::vector<Layer> read_layers(const JsonReader& reader, const Json& value, const std::string& pointer) {
  return read_layer_array<Layer>(reader, value, pointer, read_layer);
}

}  // namespace pita::scene::detail
