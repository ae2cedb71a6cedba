// The layer kinds (internal to src/scene/): one row per kind, its "type",
// the fields it takes, how it is read and whether 3D scenes draw it. The two
// tables, of arrow scenes (arrow_layer_reader.cpp) and of pose scenes
// (pose_layer_reader.cpp), are the only lists of layer kinds; every message,
// the schema test and the README derive theirs from them (figure_reader.cpp).
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "scene/figure.hpp"
#include "scene/layer_fields.hpp"

namespace pita::scene::detail {

// One kind of layer: its "type", the fields it takes and how it is read.
template <typename LayerType>
struct LayerKind {
  std::string_view type;
  std::span<const std::string_view> fields;
  LayerType (*read)(const Fields&);
  bool in_space = false;  // pose layers that 3D scenes draw too (render/layers/pose_layers.hpp)
};

std::span<const LayerKind<Layer>> arrow_layer_table();
std::span<const LayerKind<PoseLayer>> pose_layer_table();

// Kinds that both kinds of scene draw: their fields and readers (`poses`: in
// a pose scene).
inline constexpr std::array<std::string_view, 5> kLabelFields = {"type", "text", "at", "size", "color"};
inline constexpr std::array<std::string_view, 5> kMeasuresFields = {"type", "show", "at", "size", "color"};
inline constexpr std::array<std::string_view, 12> kPlotFields = {
    "type", "box", "of", "methods", "colors", "point", "samples", "color", "width", "opacity", "dash", "marks"};
inline constexpr std::array<std::string_view, 10> kShapesFields = {
    "type", "color", "width", "opacity", "dash", "fill", "fill_opacity", "samples", "range", "lightness"};

LabelLayer read_label(const Fields& fields);

// "measures"; `poses`: in a pose scene (the names it may show differ,
// scene/measure_name.hpp).
MeasuresLayer read_measures(const Fields& fields, bool poses);

// "plot"; `poses`: in a pose scene, where "of": "area" and its methods are read.
PlotLayer read_plot(const Fields& fields, bool poses);

// "shapes"; `poses`: in a pose scene, where "lightness": "area" is read.
ShapesLayer read_shapes_layer(const Fields& fields, bool poses);

}  // namespace pita::scene::detail
