// Reading the figure part of a scene: "canvas" and "layers" (scene.cpp reads
// "title" and "panels", which need the scene's method and keyframes).
// Internal to src/scene/.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/figure.hpp"
#include "scene/json_reader.hpp"

namespace pita::scene::detail {

// The motion an arrow layer draws, by the alternative of the panel's keys:
// keyframe arrows, a curve through timed points, or either (labels, legends).
enum class LayerDraws { keyframes, points, either };

// The layer types of keyframe scenes and of pose scenes, in the order
// messages and the schema list them (from figure_reader.cpp's one table of
// layer kinds each).
struct LayerKindInfo {
  std::string_view type;
  std::span<const std::string_view> fields;  // "type" included
  std::size_t alternative = 0;               // its struct's index in Layer or PoseLayer
  bool in_space = false;                     // a pose layer 3D scenes draw too
  LayerDraws draws = LayerDraws::keyframes;  // an arrow layer: the keys it needs
};
std::vector<LayerKindInfo> arrow_layer_kinds();
std::vector<LayerKindInfo> pose_layer_kinds();

// "canvas": every field optional, the defaults of figure.hpp otherwise.
Canvas read_canvas(const JsonReader& reader, const Json& value, const std::string& pointer);

// "layers": an array of at most kMaxLayers layers, each {"type": ..., ...}.
std::vector<Layer> read_layers(const JsonReader& reader, const Json& value, const std::string& pointer);

// "layers" of a pose scene or panel.
std::vector<PoseLayer> read_pose_layers(const JsonReader& reader, const Json& value, const std::string& pointer);
// The same, for a 3D scene: only the kinds marked in_space in the table.
std::vector<PoseLayer> read_space_pose_layers(const JsonReader& reader, const Json& value, const std::string& pointer);

}  // namespace pita::scene::detail
