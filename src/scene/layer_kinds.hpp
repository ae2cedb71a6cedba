// The layer kinds (internal to src/scene/): one row per kind, its "type",
// the fields it takes, how it is read and whether 3D scenes draw it. The two
// tables, of arrow scenes (arrow_layer_reader.cpp) and of pose scenes
// (pose_layer_reader.cpp), are the only lists of layer kinds; every message,
// the schema test and the docs derive theirs from them (figure_reader.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>

#include "scene/figure.hpp"
#include "scene/figure_reader.hpp"
#include "scene/layer_family.hpp"
#include "scene/layer_fields.hpp"

namespace pita::scene::detail {

// The index of the struct `Kind` among the alternatives of the variant `LayerType`.
template <typename Kind, typename LayerType, std::size_t I = 0>
consteval std::size_t alternative_of() {
  if constexpr (std::is_same_v<std::variant_alternative_t<I, LayerType>, Kind>) {
    return I;
  } else {
    return alternative_of<Kind, LayerType, I + 1>();
  }
}

// One kind of layer: its "type", the fields it takes, how it is read, the
// struct it is read into (its index in the variant), and what it draws.
template <typename LayerType>
struct LayerKind {
  std::string_view type;
  std::span<const std::string_view> fields;
  LayerType (*read)(const Fields&);
  std::size_t alternative;                   // alternative_of<its struct, LayerType>()
  bool in_space = false;                     // pose layers that 3D scenes draw too (render/layers/pose_layers.hpp)
  LayerDraws draws = LayerDraws::keyframes;  // arrow layers: the keys they need
};

// The row of `layer`'s kind.
template <typename LayerType>
const LayerKind<LayerType>& kind_of(std::span<const LayerKind<LayerType>> table, const LayerType& layer) {
  for (const LayerKind<LayerType>& kind : table) {
    if (kind.alternative == layer.index()) return kind;
  }
  return table.front();  // unreachable: every alternative has its row (tests/scene/test_layer_kinds.cpp)
}

std::span<const LayerKind<Layer>> arrow_layer_table();
std::span<const LayerKind<PoseLayer>> pose_layer_table();

// Kinds that both kinds of scene draw: their fields and readers, templates
// over the family of the scene's layers (Layer or PoseLayer).
inline constexpr std::array<std::string_view, 6> kLabelFields = {"type", "text", "at", "size", "color", "place"};
inline constexpr std::array<std::string_view, 5> kMeasuresFields = {"type", "show", "at", "size", "color"};
inline constexpr std::array<std::string_view, 13> kPlotFields = {
    "type", "box", "of", "methods", "colors", "point", "samples", "color", "width", "opacity", "dash", "marks", "size"};
inline constexpr std::array<std::string_view, 11> kShapesFields = {
    "type", "color", "width", "opacity", "dash", "fill", "fill_opacity", "samples", "range", "times", "lightness"};

LabelLayer read_label(const Fields& fields);

// "measures" in a scene whose layers are `LayerType` (scene/layer_family.hpp):
// the names it may show differ (scene/measure_name.hpp).
template <class LayerType>
MeasuresLayer read_measures(const Fields& fields);

// "plot"; "of": "area" and its methods are read in pose scenes only.
template <class LayerType>
PlotLayer read_plot(const Fields& fields);

// "shapes"; "lightness": "area" is read in pose scenes only.
template <class LayerType>
ShapesLayer read_shapes_layer(const Fields& fields);

}  // namespace pita::scene::detail
