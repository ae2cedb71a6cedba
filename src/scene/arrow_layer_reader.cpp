// The layer kinds of arrow scenes: their fields, their readers and their
// table (layer_kinds.hpp); "label", "measures" and "plot" are pose layers too.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "core/methods.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/layer_kinds.hpp"
#include "scene/pose_reader.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {

constexpr std::array<std::string_view, 15> kPatternFields = {"type",     "color", "width",  "opacity", "dash",
                                                             "extended", "coils", "heads",  "dots",    "samples",
                                                             "range",    "times", "method", "options", "label"};
constexpr std::array<std::string_view, 7> kKeyframesFields = {"type",    "colors",        "width",   "opacity",
                                                              "winding", "spiral_center", "extended"};
constexpr std::array<std::string_view, 10> kTrajectoryFields = {"type",  "point",   "samples", "range",  "color",
                                                                "width", "opacity", "dash",    "method", "options"};
constexpr std::array<std::string_view, 6> kStrokeFields = {"type", "fill", "opacity", "outline", "samples", "range"};
constexpr std::array<std::string_view, 9> kBannerFields = {"type",    "text",    "font",    "fill", "opacity",
                                                           "outline", "padding", "samples", "range"};
constexpr std::array<std::string_view, 10> kDiscrepancyFields = {"type",  "predictor", "method", "scale", "color",
                                                                 "width", "opacity",   "dash",   "fill",  "samples"};
constexpr std::array<std::string_view, 3> kLegendFields = {"type", "corner", "size"};

constexpr std::array<std::string_view, 8> kGuessesFields = {"type",        "guesses", "show", "width",
                                                            "frame_color", "at",      "size", "color"};
constexpr std::array<std::string_view, 8> kGuessFields = {"t", "p", "q", "m", "w", "turns", "name", "color"};
constexpr std::array<std::string_view, 2> kGuessMeasureNames = {"discrepancy", "distance"};
constexpr std::array<GuessMeasure, 2> kGuessMeasures = {GuessMeasure::discrepancy, GuessMeasure::distance};
constexpr std::array<std::string_view, 9> kCompareFields = {"type", "method",  "color", "width", "opacity",
                                                            "dash", "samples", "at",    "size"};

constexpr std::array<std::string_view, 4> kHandleFields = {"type", "color", "width", "shapes"};
constexpr std::array<std::string_view, 9> kPointTrajectoryFields = {"type",  "curve",   "samples", "range", "color",
                                                                    "width", "opacity", "dash",    "dots"};
constexpr std::array<std::string_view, 3> kPlotOfNames = {"distance", "area", "time"};
constexpr std::array<PlotOf, 3> kPlotOfs = {PlotOf::distance, PlotOf::area, PlotOf::time};

constexpr std::array<std::string_view, 6> kPropertyTableFields = {"type", "methods", "configs", "seed", "at", "trees"};
constexpr std::array<std::string_view, 3> kTreeFields = {"title", "order", "methods"};
constexpr std::array<std::string_view, 12> kVectorsFields = {
    "type", "of", "at", "at_point", "scale", "colors", "width", "opacity", "dash", "heads", "samples", "range"};
constexpr std::array<std::string_view, 10> kFixedPointsFields = {"type",    "center", "point", "color",   "width",
                                                                 "opacity", "dash",   "dots",  "samples", "range"};

constexpr std::array<std::string_view, 2> kSpiralCenterNames = {"start", "midpoint"};
constexpr std::array<SpiralCenter, 2> kSpiralCenters = {SpiralCenter::start, SpiralCenter::middle};
constexpr std::array<std::string_view, 3> kPredictorNames = {"previous", "average", "pita"};
constexpr std::array<Predictor, 3> kPredictors = {Predictor::previous, Predictor::average, Predictor::pita};

PatternLayer read_pattern(const Fields& fields) {
  PatternLayer layer;
  read_line(fields, layer.line);
  fields.boolean("extended", layer.extended);
  fields.boolean("coils", layer.coils);
  fields.boolean("heads", layer.heads);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  read_frame_times(fields, layer.times);
  if (const Json* method = fields.get("method")) layer.method = fields.reader().method(*method, fields.at("method"));
  if (const Json* options = fields.get("options")) layer.options = read_options_patch(fields, *options);
  if (const Json* label = fields.get("label")) {
    layer.label = fields.reader().text(*label, fields.at("label"), kMaxTextLength);
  }
  fields.boolean("dots", layer.dots);
  if (layer.dots && layer.heads) {
    fields.reader().fail(fields.at("dots"),
                         "draws each frame as the dot of its point p, and \"heads\" draws it "
                         "as an arrow: choose one");
  }
  return layer;
}

KeyframesLayer read_keyframes_layer(const Fields& fields) {
  KeyframesLayer layer;
  if (const Json* colors = fields.get("colors")) {
    const std::string pointer = fields.at("colors");
    if (!colors->is_array() || colors->empty() || colors->size() > kMaxKeyframeColors) {
      fields.reader().fail(
          pointer, fmt::format("must be an array of 1 to {} colors (got {})", kMaxKeyframeColors, value_text(*colors)));
    }
    layer.colors.clear();
    for (std::size_t i = 0; i < colors->size(); ++i) {
      layer.colors.push_back(fields.reader().color((*colors)[i], element_pointer(pointer, i)));
    }
  }
  fields.number("width", kLineWidth, layer.width);
  fields.number("opacity", kOpacity, layer.opacity);
  fields.boolean("winding", layer.winding);
  fields.choice("spiral_center", kSpiralCenterNames, kSpiralCenters, layer.spiral_center);
  fields.boolean("extended", layer.extended);
  return layer;
}

TrajectoryLayer read_trajectory(const Fields& fields) {
  TrajectoryLayer layer;
  fields.choice("point", kPointNames, kPoints, layer.point);
  fields.integer("samples", 2, kMaxTrajectorySamples, layer.samples);
  read_range(fields, layer.range);
  read_line(fields, layer.line);
  if (const Json* method = fields.get("method")) layer.method = fields.reader().method(*method, fields.at("method"));
  if (const Json* options = fields.get("options")) layer.options = read_options_patch(fields, *options);
  return layer;
}

HandleLayer read_handle_layer(const Fields& fields) {
  HandleLayer layer;
  fields.color("color", layer.color);
  fields.number("width", kLineWidth, layer.width);
  fields.boolean("shapes", layer.shapes);
  return layer;
}

PointTrajectoryLayer read_point_trajectory(const Fields& fields) {
  PointTrajectoryLayer layer;
  if (const Json* curve = fields.get("curve")) {
    const PointCurveInfo* found = curve->is_string() ? find_point_curve(curve->get<std::string>()) : nullptr;
    if (found == nullptr) {
      std::vector<std::string_view> names;
      for (const PointCurveInfo& about : all_point_curves()) names.push_back(about.name);
      fields.reader().fail(fields.at("curve"),
                           "must be " + quoted_choices(names) + " (got " + value_text(*curve) + ")");
    }
    layer.curve = found->curve;
  }
  fields.integer("samples", 2, kMaxTrajectorySamples, layer.samples);
  read_range(fields, layer.range);
  read_line(fields, layer.line);
  fields.boolean("dots", layer.dots);
  return layer;
}

StrokeLayer read_stroke(const Fields& fields) {
  StrokeLayer layer;
  fields.color("fill", layer.fill);
  fields.number("opacity", kOpacity, layer.opacity);
  read_outline(fields, layer.outline);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  return layer;
}

BannerLayer read_banner(const Fields& fields) {
  BannerLayer layer;
  layer.text = fields.reader().text(fields.required("text", "the text to draw"), fields.at("text"), kMaxTextLength);
  fields.text("font", kUnbounded, layer.font);
  fields.color("fill", layer.fill);
  fields.number("opacity", kOpacity, layer.opacity);
  read_outline(fields, layer.outline);
  fields.number("padding", kFraction, layer.padding);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  return layer;
}

DiscrepancyLayer read_discrepancy(const Fields& fields) {
  DiscrepancyLayer layer;
  fields.choice("predictor", kPredictorNames, kPredictors, layer.predictor);
  if (const Json* method = fields.get("method")) {
    layer.method = fields.reader().method(*method, fields.at("method"));
  }
  fields.number("scale", kPositive, layer.scale);
  read_line(fields, layer.line);
  fields.color("fill", layer.fill);
  read_figure_samples(fields, layer.samples);
  return layer;
}

LegendLayer read_legend(const Fields& fields) {
  LegendLayer layer;
  fields.choice("corner", kCornerNames, kCorners, layer.corner);
  fields.number("size", kTextSize, layer.size);
  return layer;
}

// "guesses" (Figs. 16, 18): arrows drawn for given times, with their names
// and colours (brown, magenta, orange by default, as the paper draws L, R, E).
GuessesLayer read_guesses(const Fields& fields) {
  static const std::array<Color, 3> kGuessColors = {Color{0.55, 0.27, 0.07, 1.0}, Color{0.85, 0.0, 0.85, 1.0},
                                                    Color{1.0, 0.55, 0.0, 1.0}};
  GuessesLayer layer;
  const JsonReader& reader = fields.reader();
  const Json& list = fields.required("guesses", "the arrows drawn, [{\"t\", \"p\", \"q\"}, ...]");
  const std::string at = fields.at("guesses");
  if (!list.is_array() || list.empty() || list.size() > static_cast<std::size_t>(kMaxGuesses)) {
    reader.fail(at, fmt::format("must be an array of 1 to {} arrows {{\"t\", \"p\", \"q\"}} (got {})", kMaxGuesses,
                                value_text(list)));
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string item_at = element_pointer(at, i);
    const Json& item = list[i];
    reader.object(item, item_at, "a guess");
    reader.check_fields(item, item_at, kGuessFields);
    Guess guess;
    const Fields guess_fields(reader, item, item_at);
    guess.t = reader.number(guess_fields.required("t", "the time of the guessed frame"), guess_fields.at("t"));
    Json arrow_form = item;
    arrow_form.erase("t");
    arrow_form.erase("name");
    arrow_form.erase("color");
    guess.arrow = reader.arrow(arrow_form, item_at);
    guess.name = fmt::format("G{}", i + 1);
    guess_fields.text("name", kMaxTextLength, guess.name);
    guess.color = kGuessColors[i % kGuessColors.size()];
    guess_fields.color("color", guess.color);
    layer.guesses.push_back(std::move(guess));
  }
  if (const Json* show = fields.get("show")) {
    const std::string show_at = fields.at("show");
    if (!show->is_array() || show->empty() || show->size() > kGuessMeasureNames.size()) {
      reader.fail(show_at, fmt::format("must be a list of 1 to {} of {} (got {})", kGuessMeasureNames.size(),
                                       quoted_choices(kGuessMeasureNames), value_text(*show)));
    }
    layer.show.clear();
    for (std::size_t i = 0; i < show->size(); ++i) {
      layer.show.push_back(reader.choice((*show)[i], element_pointer(show_at, i), kGuessMeasureNames, kGuessMeasures));
    }
  }
  fields.number("width", kLineWidth, layer.width);
  fields.color("frame_color", layer.frame_color);
  read_text_place(fields, layer.at, layer.corner);
  fields.number("size", kTextSize, layer.size);
  fields.color("color", layer.color);
  return layer;
}

// "compare" (Fig. B.30): another method's pattern over the panel's.
CompareLayer read_compare(const Fields& fields) {
  CompareLayer layer;
  layer.method =
      fields.reader().method(fields.required("method", "the method compared with the panel's"), fields.at("method"));
  layer.method_name = std::string(info(layer.method).id);
  read_line(fields, layer.line);
  read_figure_samples(fields, layer.samples);
  read_text_place(fields, layer.at, layer.corner);
  fields.number("size", kTextSize, layer.size);
  return layer;
}

constexpr std::array<std::string_view, 2> kVectorKindNames = {"velocity", "acceleration"};
constexpr std::array<VectorKind, 2> kVectorKinds = {VectorKind::velocity, VectorKind::acceleration};
constexpr std::array<std::string_view, 3> kVectorAtNames = {"both", "p", "q"};
constexpr std::array<int, 3> kVectorAts = {3, 1, 2};  // bit 1: p, bit 2: q
constexpr std::array<std::string_view, 2> kAtPointNames = {"tail", "head"};
constexpr std::array<bool, 2> kTailAtPoint = {true, false};
constexpr std::array<std::string_view, 3> kCenterNames = {"global", "acceleration", "velocity"};
constexpr std::array<CenterKind, 3> kCenters = {CenterKind::global, CenterKind::acceleration, CenterKind::velocity};

// "vectors": the defaults follow the paper's figures: accelerations at p
// black and at q brown (Figs. 9, 14), velocities dark green (Fig. 15).
VectorsLayer read_vectors(const Fields& fields) {
  VectorsLayer layer;
  fields.choice("of", kVectorKindNames, kVectorKinds, layer.of);
  if (layer.of == VectorKind::velocity) {
    layer.scale = 0.25;
    layer.color_p = layer.color_q = Color{0.0, 100.0 / 255.0, 0.0, 1.0};  // #006400
  }
  int at = 3;
  fields.choice("at", kVectorAtNames, kVectorAts, at);
  layer.at_p = (at & 1) != 0;
  layer.at_q = (at & 2) != 0;
  fields.choice("at_point", kAtPointNames, kTailAtPoint, layer.tail_at_point);
  fields.number("scale", kPositive, layer.scale);
  if (const Json* colors = fields.get("colors")) {
    const std::string pointer = fields.at("colors");
    if (!colors->is_array() || colors->empty() || colors->size() > 2) {
      fields.reader().fail(pointer,
                           "must be an array of 1 or 2 colors: [at p, at q] (got " + value_text(*colors) + ")");
    }
    layer.color_p = fields.reader().color((*colors)[0], element_pointer(pointer, 0));
    layer.color_q =
        colors->size() == 2 ? fields.reader().color((*colors)[1], element_pointer(pointer, 1)) : layer.color_p;
  }
  fields.number("width", kLineWidth, layer.line.width);
  fields.number("opacity", kOpacity, layer.line.opacity);
  if (const Json* dash = fields.get("dash")) {
    layer.line.dash = read_dash(fields.reader(), *dash, fields.at("dash"));
  }
  fields.boolean("heads", layer.heads);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  return layer;
}

FixedPointsLayer read_fixed_points(const Fields& fields) {
  FixedPointsLayer layer;
  fields.choice("center", kCenterNames, kCenters, layer.center);
  fields.choice("point", kPointNames, kPoints, layer.point);
  read_line(fields, layer.line);
  fields.boolean("dots", layer.dots);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  return layer;
}

// A list of methods through three keyframes (the property table's columns, a tree's leaves).
std::vector<Method> read_three_keyframe_methods(const JsonReader& reader, const Json& methods, const std::string& at) {
  if (!methods.is_array() || methods.empty()) {
    reader.fail(at, "must be a non-empty array of method names (for example [\"P1\", \"P6\"])");
  }
  std::vector<Method> out;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string item = at + "/" + std::to_string(i);
    const Method m = reader.method(methods[i], item);
    if (info(m).keyframe_count != 3) {
      reader.fail(item, fmt::format("{} takes {} keyframes; the properties of Sec. 4 are measured for the "
                                    "methods through three",
                                    info(m).id, info(m).keyframe_count));
    }
    out.push_back(m);
  }
  return out;
}

// "trees": [{"title", "order": [property names], "methods"}]; the names are
// checked against the properties when the table is drawn (render/).
std::vector<DecisionTreeSpec> read_trees(const JsonReader& reader, const Json& trees, const std::string& at) {
  if (!trees.is_array() || trees.size() > kMaxDecisionTrees) {
    reader.fail(
        at, fmt::format("must be a list of at most {} decision trees (got {})", kMaxDecisionTrees, value_text(trees)));
  }
  std::vector<DecisionTreeSpec> out;
  for (std::size_t i = 0; i < trees.size(); ++i) {
    const std::string pointer = element_pointer(at, i);
    const Json& tree = trees[i];
    reader.object(tree, pointer, "a decision tree");
    reader.check_fields(tree, pointer, kTreeFields);
    DecisionTreeSpec spec;
    spec.pointer = pointer;
    if (const Json* title = JsonReader::member(tree, "title"))
      spec.title = reader.text(*title, pointer + "/title", 200);
    const Json* order = JsonReader::member(tree, "order");
    if (order == nullptr) reader.fail(pointer, "a decision tree lists the properties it asks, in order: \"order\"");
    if (!order->is_array() || order->empty() || order->size() > 20) {
      reader.fail(pointer + "/order", fmt::format("must be a list of 1 to 20 property names, such as "
                                                  "[\"winding-aware\", \"handle-invariant\"] (got {})",
                                                  value_text(*order)));
    }
    for (std::size_t k = 0; k < order->size(); ++k) {
      spec.order.push_back(reader.text((*order)[k], element_pointer(pointer + "/order", k), 40));
    }
    if (const Json* methods = JsonReader::member(tree, "methods")) {
      spec.methods = read_three_keyframe_methods(reader, *methods, pointer + "/methods");
    }
    out.push_back(std::move(spec));
  }
  return out;
}

PropertyTableLayer read_property_table(const Fields& fields) {
  PropertyTableLayer layer;
  if (const Json* methods = fields.get("methods")) {
    layer.methods = read_three_keyframe_methods(fields.reader(), *methods, fields.at("methods"));
  }
  if (const Json* trees = fields.get("trees")) layer.trees = read_trees(fields.reader(), *trees, fields.at("trees"));
  fields.integer("configs", 1, kMaxTableConfigs, layer.configs);
  fields.integer("seed", 0, 2147483647, layer.seed);
  if (const Json* at = fields.get("at")) layer.at = fields.reader().point(*at, fields.at("at"));
  return layer;
}

}  // namespace

LabelLayer read_label(const Fields& fields) {
  LabelLayer layer;
  layer.text = fields.reader().text(fields.required("text", "the text to draw"), fields.at("text"), kMaxTextLength);
  layer.at = fields.reader().point(fields.required("at", "the point [x, y] of the text"), fields.at("at"));
  fields.number("size", kTextSize, layer.size);
  fields.color("color", layer.color);
  fields.choice("place", kLabelPlaceNames, kLabelPlaces, layer.avoid_data);
  return layer;
}

template <class LayerType>
MeasuresLayer read_measures(const Fields& fields) {
  MeasuresLayer layer;
  const JsonReader& reader = fields.reader();
  layer.show = default_measures<LayerType>();
  if (const Json* show = fields.get("show")) {
    const std::string at = fields.at("show");
    if (!show->is_array() || show->empty() || show->size() > kMaxMeasures) {
      reader.fail(at, fmt::format("must be a list of 1 to {} measure names (got {})", kMaxMeasures, value_text(*show)));
    }
    layer.show.clear();
    for (std::size_t i = 0; i < show->size(); ++i) {
      const std::string item_at = element_pointer(at, i);
      auto parsed = parse_measure<LayerType>(reader.string((*show)[i], item_at));
      if (const std::string* reason = std::get_if<std::string>(&parsed)) reader.fail(item_at, *reason);
      if (std::get<MeasureName>(parsed).panel) {
        reader.fail(item_at, fmt::format("\"{}\" compares with another panel, which only a claim does "
                                         "(docs/reference/check.md \"Claims\")",
                                         std::get<MeasureName>(parsed).text));
      }
      const MeasureKind kind = std::get<MeasureName>(parsed).kind;
      if (kind == MeasureKind::frame_distance || kind == MeasureKind::guess_distance ||
          kind == MeasureKind::guess_discrepancy) {
        reader.fail(item_at, fmt::format("\"{}\" is measured by claims only (docs/reference/check.md \"Claims\"); "
                                         "a \"compare\" or \"guesses\" layer prints it",
                                         std::get<MeasureName>(parsed).text));
      }
      if (kind == MeasureKind::property) {
        reader.fail(item_at,
                    fmt::format("\"{}\" is measured by claims only (docs/reference/check.md \"Claims\"); the property "
                                "table of pita audit prints every property",
                                std::get<MeasureName>(parsed).text));
      }
      layer.show.push_back(std::move(std::get<MeasureName>(parsed)));
    }
  }
  read_text_place(fields, layer.at, layer.corner);
  fields.number("size", kTextSize, layer.size);
  fields.color("color", layer.color);
  return layer;
}

template <class LayerType>
PlotLayer read_plot(const Fields& fields) {
  PlotLayer layer;
  const Json& box = fields.required("box", "the box {\"min\": [x, y], \"max\": [x, y]} the plot fills");
  const std::string at = fields.at("box");
  fields.reader().object(box, at, "a box {\"min\": [x, y], \"max\": [x, y]}");
  fields.reader().check_fields(box, at, kBoxFields);
  layer.box = read_box(Fields(fields.reader(), box, at));
  fields.choice("point", kPointNames, kPoints, layer.point);
  fields.integer("samples", 2, kMaxTrajectorySamples, layer.samples);
  read_line(fields, layer.line);
  fields.boolean("marks", layer.marks);
  fields.number("size", kTextSize, layer.size);
  fields.choice("of", kPlotOfNames, kPlotOfs, layer.of);
  if (layer.of == PlotOf::area && !LayerFamily<LayerType>::moves_poses) {
    fields.reader().fail(fields.at("of"),
                         "\"area\" plots the area of a pose scene's shapes; an arrow scene's "
                         "plot is of \"distance\" or \"time\"");
  }
  for (const std::string_view key : {std::string_view("methods"), std::string_view("colors")}) {
    if (layer.of != PlotOf::area && fields.get(key) != nullptr) {
      fields.reader().fail(fields.at(key), "is read only with \"of\": \"area\"");
    }
  }
  if (const Json* methods = fields.get("methods")) {
    const std::string where = fields.at("methods");
    if (!methods->is_array() || methods->empty() || methods->size() > kMaxPlotMethods) {
      fields.reader().fail(where, fmt::format("must be an array of 1 to {} pose methods (got {})", kMaxPlotMethods,
                                              value_text(*methods)));
    }
    for (std::size_t i = 0; i < methods->size(); ++i) {
      layer.methods.push_back(detail::read_pose_method(fields.reader(), (*methods)[i], element_pointer(where, i)));
    }
  }
  if (layer.of == PlotOf::area) layer.colors = read_colors(fields, layer.colors);
  return layer;
}

template MeasuresLayer read_measures<Layer>(const Fields&);
template MeasuresLayer read_measures<PoseLayer>(const Fields&);
template PlotLayer read_plot<Layer>(const Fields&);
template PlotLayer read_plot<PoseLayer>(const Fields&);

namespace {

// The layer kinds of keyframe (arrow) scenes, in the order messages, the
// schema and docs/reference/render.md list them.
template <typename Kind>
constexpr std::size_t arrow_alternative = alternative_of<Kind, Layer>();

constexpr std::array<LayerKind<Layer>, 18> kArrowLayerKinds{{
    {"pattern", kPatternFields, [](const Fields& f) -> Layer { return read_pattern(f); },
     arrow_alternative<PatternLayer>},
    {"keyframes", kKeyframesFields, [](const Fields& f) -> Layer { return read_keyframes_layer(f); },
     arrow_alternative<KeyframesLayer>},
    {"trajectory", kTrajectoryFields, [](const Fields& f) -> Layer { return read_trajectory(f); },
     arrow_alternative<TrajectoryLayer>},
    {"stroke", kStrokeFields, [](const Fields& f) -> Layer { return read_stroke(f); }, arrow_alternative<StrokeLayer>},
    {"banner", kBannerFields, [](const Fields& f) -> Layer { return read_banner(f); }, arrow_alternative<BannerLayer>},
    {"discrepancy", kDiscrepancyFields, [](const Fields& f) -> Layer { return read_discrepancy(f); },
     arrow_alternative<DiscrepancyLayer>},
    {"label", kLabelFields, [](const Fields& f) -> Layer { return read_label(f); }, arrow_alternative<LabelLayer>,
     false, LayerDraws::either},
    {"legend", kLegendFields, [](const Fields& f) -> Layer { return read_legend(f); }, arrow_alternative<LegendLayer>,
     false, LayerDraws::either},
    {"plot", kPlotFields, [](const Fields& f) -> Layer { return read_plot<Layer>(f); }, arrow_alternative<PlotLayer>},
    {"point-trajectory", kPointTrajectoryFields, [](const Fields& f) -> Layer { return read_point_trajectory(f); },
     arrow_alternative<PointTrajectoryLayer>, false, LayerDraws::points},
    {"shapes", kShapesFields, [](const Fields& f) -> Layer { return read_shapes_layer<Layer>(f); },
     arrow_alternative<ShapesLayer>},
    {"handle", kHandleFields, [](const Fields& f) -> Layer { return read_handle_layer(f); },
     arrow_alternative<HandleLayer>},
    {"property-table", kPropertyTableFields, [](const Fields& f) -> Layer { return read_property_table(f); },
     arrow_alternative<PropertyTableLayer>},
    {"measures", kMeasuresFields, [](const Fields& f) -> Layer { return read_measures<Layer>(f); },
     arrow_alternative<MeasuresLayer>},
    {"vectors", kVectorsFields, [](const Fields& f) -> Layer { return read_vectors(f); },
     arrow_alternative<VectorsLayer>},
    {"fixed-points", kFixedPointsFields, [](const Fields& f) -> Layer { return read_fixed_points(f); },
     arrow_alternative<FixedPointsLayer>},
    {"guesses", kGuessesFields, [](const Fields& f) -> Layer { return read_guesses(f); },
     arrow_alternative<GuessesLayer>},
    {"compare", kCompareFields, [](const Fields& f) -> Layer { return read_compare(f); },
     arrow_alternative<CompareLayer>},
}};

}  // namespace

std::span<const LayerKind<Layer>> arrow_layer_table() { return kArrowLayerKinds; }

}  // namespace pita::scene::detail
