// The layer kinds of pose scenes: their fields, their readers and their
// table (layer_kinds.hpp); "shapes" is an arrow layer too.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "scene/layer_kinds.hpp"
#include "scene/pose_reader.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 2> kLightnessNames = {"constant", "area"};
constexpr std::array<bool, 2> kLightnessByArea = {false, true};
constexpr std::array<std::string_view, 13> kFieldFields = {"type",  "box",   "columns",    "rows", "scale",
                                                           "color", "width", "opacity",    "dash", "curves",
                                                           "curve", "range", "fixed_point"};
constexpr std::array<std::string_view, 5> kPosesFields = {"type", "colors", "width", "fill_opacity", "inserted"};
constexpr std::array<std::string_view, 8> kVelocitiesFields = {"type",    "scale", "color",   "width",
                                                               "opacity", "dash",  "samples", "range"};
constexpr std::array<std::string_view, 7> kPathsFields = {"type",  "samples", "range", "color",
                                                          "width", "opacity", "dash"};
constexpr std::array<std::string_view, 7> kExistenceFields = {"type",        "columns",  "rows",     "fill",
                                                              "exists_fill", "boundary", "trapezoid"};
constexpr std::array<std::string_view, 12> kPatchFields = {"type",  "columns",      "rows",    "regular",
                                                           "color", "width",        "opacity", "dash",
                                                           "fill",  "fill_opacity", "corner",  "grid"};
constexpr std::array<std::string_view, 6> kAraFields = {"type", "at", "size", "color", "digits", "grid"};
constexpr std::array<std::string_view, 13> kSweptFields = {
    "type", "edge",     "samples", "range",    "trace_samples", "instants", "segments",
    "ends", "envelope", "grazing", "claim_at", "size",          "color"};
constexpr std::array<std::string_view, 12> kVersusFields = {
    "type", "method", "at", "power", "color", "width", "opacity", "dash", "fill", "fill_opacity", "samples", "range"};
constexpr std::array<std::string_view, 11> kSam3dExistenceFields = {
    "type", "steps", "subdivisions", "step", "color", "width", "opacity", "dash", "fill", "fill_opacity", "paper"};
constexpr Interval kSafeCurveStep{0.001, 0.1};

PosesLayer read_poses_layer(const Fields& fields) {
  PosesLayer layer;
  layer.colors = read_colors(fields, layer.colors);
  fields.number("width", kLineWidth, layer.width);
  fields.number("fill_opacity", kOpacity, layer.fill_opacity);
  if (fields.get("inserted") != nullptr) {
    layer.inserted = fields.reader().color(*fields.get("inserted"), fields.at("inserted"));
  }
  return layer;
}

VelocitiesLayer read_velocities(const Fields& fields) {
  VelocitiesLayer layer;
  fields.number("scale", kPositive, layer.scale);
  read_line(fields, layer.line);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  return layer;
}

FieldLayer read_field(const Fields& fields) {
  FieldLayer layer;
  const Json& box = fields.required("box", "the box {\"min\": [x, y], \"max\": [x, y]} the grid covers");
  const std::string at = fields.at("box");
  fields.reader().object(box, at, "a box {\"min\": [x, y], \"max\": [x, y]}");
  fields.reader().check_fields(box, at, kBoxFields);
  layer.box = read_box(Fields(fields.reader(), box, at));
  fields.integer("columns", 2, kMaxFieldSide, layer.columns);
  fields.integer("rows", 2, kMaxFieldSide, layer.rows);
  fields.number("scale", kPositive, layer.scale);
  read_line(fields, layer.line);
  fields.integer("curves", 0, kMaxFieldSide, layer.curves);
  read_line_object(fields, "curve", layer.curve);
  read_range(fields, layer.range);
  fields.boolean("fixed_point", layer.fixed_point);
  return layer;
}

PathsLayer read_paths(const Fields& fields) {
  PathsLayer layer;
  fields.integer("samples", 2, kMaxTrajectorySamples, layer.samples);
  read_range(fields, layer.range);
  read_line(fields, layer.line);
  return layer;
}

ExistenceLayer read_existence(const Fields& fields) {
  const JsonReader& reader = fields.reader();
  ExistenceLayer layer;
  fields.integer("columns", 2, kMaxExistenceSide, layer.columns);
  fields.integer("rows", 2, kMaxExistenceSide, layer.rows);
  if (static_cast<long long>(layer.columns) * layer.rows > kMaxExistenceCells) {
    reader.fail(fields.at("rows"), fmt::format("columns x rows must be at most {} (got {} x {})", kMaxExistenceCells,
                                               layer.columns, layer.rows));
  }
  fields.color("fill", layer.fill);
  if (const Json* exists = fields.get("exists_fill")) {
    if (exists->is_string() && exists->get<std::string>() == "none") {
      layer.exists_fill.reset();
    } else {
      layer.exists_fill = reader.color(*exists, fields.at("exists_fill"));
    }
  }
  read_line_object(fields, "boundary", layer.boundary);
  read_line_object(fields, "trapezoid", layer.trapezoid);
  return layer;
}

Sam3dExistenceLayer read_sam3d_existence(const Fields& fields) {
  Sam3dExistenceLayer layer;
  fields.integer("steps", 1, kMaxSam3dExistenceSteps, layer.steps);
  fields.integer("subdivisions", 0, kMaxSam3dExistenceSubdivisions, layer.subdivisions);
  fields.number("step", kSafeCurveStep, layer.step);
  read_line(fields, layer.line);
  if (const Json* fill = fields.get("fill")) {
    if (fill->is_string() && fill->get<std::string>() == "none") {
      layer.fill.reset();
    } else {
      layer.fill = fields.reader().color(*fill, fields.at("fill"));
    }
  }
  fields.number("fill_opacity", kOpacity, layer.fill_opacity);
  // "paper": false, or a line style for the paper's stated bounds.
  if (const Json* paper = fields.get("paper")) {
    if (paper->is_boolean()) {
      layer.paper = paper->get<bool>();
    } else if (!paper->is_object()) {
      fields.reader().fail(fields.at("paper"), fmt::format("must be true, false or a line style {{\"color\", "
                                                           "\"width\", \"opacity\", \"dash\"}} (got {})",
                                                           value_text(*paper)));
    } else {
      read_line_object(fields, "paper", layer.paper_line);
    }
  }
  return layer;
}

PatchLayer read_patch(const Fields& fields) {
  PatchLayer layer;
  fields.integer("columns", 2, kMaxPatchSide, layer.columns);
  fields.integer("rows", 2, kMaxPatchSide, layer.rows);
  fields.boolean("regular", layer.regular);
  read_line(fields, layer.line);
  fields.color("fill", layer.fill);
  fields.number("fill_opacity", kOpacity, layer.fill_opacity);
  if (fields.get("corner") != nullptr) {  // unset members keep the patch's line
    LineStyle corner = layer.line;
    read_line_object(fields, "corner", corner);
    layer.corner = corner;
  }
  if (fields.get("grid") != nullptr) {  // unset members: a thin grey line
    LineStyle grid{Color{0.45, 0.45, 0.45, 1.0}, 0.8, 1.0, {}};
    read_line_object(fields, "grid", grid);
    layer.grid = grid;
  }
  return layer;
}

AraLayer read_ara(const Fields& fields) {
  AraLayer layer;
  layer.at = fields.reader().point(fields.required("at", "the point [x, y] of the text"), fields.at("at"));
  fields.number("size", kTextSize, layer.size);
  fields.color("color", layer.color);
  fields.integer("digits", 0, kMaxAraDigits, layer.digits);
  fields.integer("grid", 2, kMaxAraGrid, layer.grid);
  return layer;
}

SweptLayer read_swept(const Fields& fields) {
  SweptLayer layer;
  const Json& edge = fields.required("edge", "the edge [[x, y], [x, y]] in reference coordinates");
  const std::string pointer = fields.at("edge");
  if (!edge.is_array() || edge.size() != 2) {
    fields.reader().fail(pointer, "must be an array of two points [[x, y], [x, y]] (got " + value_text(edge) + ")");
  }
  for (std::size_t i = 0; i < 2; ++i) layer.edge[i] = fields.reader().point(edge[i], element_pointer(pointer, i));
  if (layer.edge[0] == layer.edge[1]) {
    fields.reader().fail(element_pointer(pointer, 1), "the edge's two ends must differ");
  }
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  fields.integer("trace_samples", 2, kMaxTrajectorySamples, layer.trace_samples);
  fields.integer("instants", 0, kMaxSweptInstants, layer.instants);
  read_optional_line(fields, "segments", layer.segments);
  read_optional_line(fields, "ends", layer.ends);
  read_optional_line(fields, "envelope", layer.envelope);
  read_optional_line(fields, "grazing", layer.grazing);
  if (const Json* at = fields.get("claim_at")) layer.claim_at = fields.reader().point(*at, fields.at("claim_at"));
  fields.number("size", kTextSize, layer.size);
  fields.color("color", layer.color);
  return layer;
}

VersusLayer read_versus(const Fields& fields) {
  const JsonReader& reader = fields.reader();
  VersusLayer layer;
  layer.method =
      read_pose_method(reader, fields.required("method", "the pose method to compare with"), fields.at("method"));
  if (const Json* at = fields.get("at")) {
    const std::string pointer = fields.at("at");
    if (!at->is_array() || at->empty() || at->size() > kMaxCompareTimes) {
      reader.fail(pointer,
                  fmt::format("must be an array of 1 to {} times (got {})", kMaxCompareTimes, value_text(*at)));
    }
    for (std::size_t i = 0; i < at->size(); ++i) {
      layer.at.push_back(reader.number((*at)[i], element_pointer(pointer, i)));
    }
  }
  fields.integer("power", 1, kMaxComparePower, layer.power);
  read_line(fields, layer.line);
  fields.color("fill", layer.fill);
  fields.number("fill_opacity", kOpacity, layer.fill_opacity);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  return layer;
}

}  // namespace

template <class LayerType>
ShapesLayer read_shapes_layer(const Fields& fields) {
  ShapesLayer layer;
  read_line(fields, layer.line);
  fields.color("fill", layer.fill);
  fields.number("fill_opacity", kOpacity, layer.fill_opacity);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  read_frame_times(fields, layer.times);
  fields.choice("lightness", kLightnessNames, kLightnessByArea, layer.lightness_by_area);
  if (layer.lightness_by_area && !LayerFamily<LayerType>::moves_poses) {
    fields.reader().fail(fields.at("lightness"),
                         "\"area\" shades a pose scene's shapes by their area; an arrow "
                         "scene's carry a similarity (use \"constant\")");
  }
  return layer;
}

template ShapesLayer read_shapes_layer<Layer>(const Fields&);
template ShapesLayer read_shapes_layer<PoseLayer>(const Fields&);

namespace {

// The layer kinds of pose scenes.
template <typename Kind>
constexpr std::size_t pose_alternative = alternative_of<Kind, PoseLayer>();

constexpr std::array<LayerKind<PoseLayer>, 14> kPoseLayerKinds{{
    {"shapes", kShapesFields, [](const Fields& f) -> PoseLayer { return read_shapes_layer<PoseLayer>(f); },
     pose_alternative<ShapesLayer>, true},
    {"poses", kPosesFields, [](const Fields& f) -> PoseLayer { return read_poses_layer(f); },
     pose_alternative<PosesLayer>, true},
    {"velocities", kVelocitiesFields, [](const Fields& f) -> PoseLayer { return read_velocities(f); },
     pose_alternative<VelocitiesLayer>, true},
    {"paths", kPathsFields, [](const Fields& f) -> PoseLayer { return read_paths(f); }, pose_alternative<PathsLayer>,
     true},
    {"existence", kExistenceFields, [](const Fields& f) -> PoseLayer { return read_existence(f); },
     pose_alternative<ExistenceLayer>},
    {"sam3d-existence", kSam3dExistenceFields, [](const Fields& f) -> PoseLayer { return read_sam3d_existence(f); },
     pose_alternative<Sam3dExistenceLayer>},
    {"label", kLabelFields, [](const Fields& f) -> PoseLayer { return read_label(f); }, pose_alternative<LabelLayer>},
    {"patch", kPatchFields, [](const Fields& f) -> PoseLayer { return read_patch(f); }, pose_alternative<PatchLayer>,
     true},
    {"plot", kPlotFields, [](const Fields& f) -> PoseLayer { return read_plot<PoseLayer>(f); },
     pose_alternative<PlotLayer>},
    {"ara", kAraFields, [](const Fields& f) -> PoseLayer { return read_ara(f); }, pose_alternative<AraLayer>},
    {"measures", kMeasuresFields, [](const Fields& f) -> PoseLayer { return read_measures<PoseLayer>(f); },
     pose_alternative<MeasuresLayer>},
    {"swept", kSweptFields, [](const Fields& f) -> PoseLayer { return read_swept(f); }, pose_alternative<SweptLayer>},
    {"versus", kVersusFields, [](const Fields& f) -> PoseLayer { return read_versus(f); },
     pose_alternative<VersusLayer>},
    {"field", kFieldFields, [](const Fields& f) -> PoseLayer { return read_field(f); }, pose_alternative<FieldLayer>},
}};

}  // namespace

std::span<const LayerKind<PoseLayer>> pose_layer_table() { return kPoseLayerKinds; }

}  // namespace pita::scene::detail
