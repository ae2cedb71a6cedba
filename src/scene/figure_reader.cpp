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
#include "scene/pose_reader.hpp"
#include "scene/timing_reader.hpp"

namespace pita::scene::detail {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();

// Bounds shared by several fields (schema/scene.schema.json says the same).
constexpr Interval kLineWidth{0.0, 100.0, /*min_open=*/true};
constexpr Interval kOpacity{0.0, 1.0};
constexpr Interval kPositive{0.0, kInfinity, /*min_open=*/true};
constexpr Interval kFraction{0.0, 0.45};  // margin, padding
constexpr Interval kTextSize{0.0, 200.0, /*min_open=*/true};

constexpr std::array<std::string_view, 8> kCanvasFields = {
    "width", "height", "background", "view", "margin", "y_axis", "columns", "font"};
constexpr std::array<std::string_view, 2> kBoxFields = {"min", "max"};
constexpr std::array<std::string_view, 4> kLineFields = {"color", "width", "opacity", "dash"};

constexpr std::array<std::string_view, 15> kPatternFields = {
    "type", "color", "width", "opacity", "dash", "extended", "coils", "heads", "dots", "samples", "range",
    "times", "method", "options", "label"};
constexpr std::array<std::string_view, 7> kKeyframesFields = {
    "type", "colors", "width", "opacity", "winding", "spiral_center", "extended"};
constexpr std::array<std::string_view, 8> kTrajectoryFields = {
    "type", "point", "samples", "range", "color", "width", "opacity", "dash"};
constexpr std::array<std::string_view, 6> kStrokeFields = {"type",    "fill",    "opacity",
                                                           "outline", "samples", "range"};
constexpr std::array<std::string_view, 9> kBannerFields = {
    "type", "text", "font", "fill", "opacity", "outline", "padding", "samples", "range"};
constexpr std::array<std::string_view, 10> kDiscrepancyFields = {
    "type", "predictor", "method", "scale", "color", "width", "opacity", "dash", "fill", "samples"};
constexpr std::array<std::string_view, 5> kLabelFields = {"type", "text", "at", "size", "color"};
constexpr std::array<std::string_view, 3> kLegendFields = {"type", "corner", "size"};
constexpr std::array<std::string_view, 5> kMeasuresFields = {"type", "show", "at", "size", "color"};

constexpr std::array<std::string_view, 8> kGuessesFields = {
    "type", "guesses", "show", "width", "frame_color", "at", "size", "color"};
constexpr std::array<std::string_view, 8> kGuessFields = {"t", "p", "q", "m", "w", "turns", "name", "color"};
constexpr std::array<std::string_view, 2> kGuessMeasureNames = {"discrepancy", "distance"};
constexpr std::array<GuessMeasure, 2> kGuessMeasures = {GuessMeasure::discrepancy, GuessMeasure::distance};
constexpr std::array<std::string_view, 9> kCompareFields = {
    "type", "method", "color", "width", "opacity", "dash", "samples", "at", "size"};

constexpr std::array<std::string_view, 4> kHandleFields = {"type", "color", "width", "shapes"};
constexpr std::array<std::string_view, 9> kPointTrajectoryFields = {
    "type", "curve", "samples", "range", "color", "width", "opacity", "dash", "dots"};
constexpr std::array<std::string_view, 12> kPlotFields = {
    "type", "box", "of", "methods", "colors", "point", "samples", "color", "width", "opacity", "dash", "marks"};
constexpr std::array<std::string_view, 2> kPlotOfNames = {"distance", "area"};
constexpr std::array<PlotOf, 2> kPlotOfs = {PlotOf::distance, PlotOf::area};

constexpr std::array<std::string_view, 5> kPropertyTableFields = {"type", "methods", "configs", "seed", "at"};
constexpr std::array<std::string_view, 12> kVectorsFields = {
    "type", "of", "at", "at_point", "scale", "colors", "width", "opacity", "dash", "heads", "samples", "range"};
constexpr std::array<std::string_view, 10> kFixedPointsFields = {
    "type", "center", "point", "color", "width", "opacity", "dash", "dots", "samples", "range"};

constexpr std::array<std::string_view, 2> kYAxisNames = {"up", "down"};
constexpr std::array<bool, 2> kYUp = {true, false};
constexpr std::array<std::string_view, 2> kSpiralCenterNames = {"start", "midpoint"};
constexpr std::array<SpiralCenter, 2> kSpiralCenters = {SpiralCenter::start,
                                                        SpiralCenter::middle};
constexpr std::array<std::string_view, 3> kPredictorNames = {"previous", "average", "pita"};
constexpr std::array<Predictor, 3> kPredictors = {Predictor::previous, Predictor::average,
                                                  Predictor::pita};
constexpr std::array<std::string_view, 4> kCornerNames = {"top-left", "top-right", "bottom-left",
                                                          "bottom-right"};
constexpr std::array<LegendLayer::Corner, 4> kCorners = {
    LegendLayer::Corner::top_left, LegendLayer::Corner::top_right,
    LegendLayer::Corner::bottom_left, LegendLayer::Corner::bottom_right};

// An object being read: its members and where it is.
class Fields {
 public:
  Fields(const JsonReader& reader, const Json& object, std::string pointer)
      : reader_(reader), object_(object), pointer_(std::move(pointer)) {}

  const JsonReader& reader() const { return reader_; }
  const Json& object() const { return object_; }
  const std::string& pointer() const { return pointer_; }
  const Json* get(std::string_view key) const {
    return JsonReader::member(object_, std::string(key));
  }
  std::string at(std::string_view key) const { return member_pointer(pointer_, key); }

  // Each reads the member `key` into `out` when it is there.
  void number(std::string_view key, const Interval& bounds, double& out) const {
    if (const Json* value = get(key)) out = reader_.number(*value, at(key), bounds);
  }
  void boolean(std::string_view key, bool& out) const {
    if (const Json* value = get(key)) out = reader_.boolean(*value, at(key));
  }
  void color(std::string_view key, Color& out) const {
    if (const Json* value = get(key)) out = reader_.color(*value, at(key));
  }
  void color(std::string_view key, std::optional<Color>& out) const {
    if (const Json* value = get(key)) out = reader_.color(*value, at(key));
  }
  void text(std::string_view key, std::size_t max_length, std::string& out) const {
    if (const Json* value = get(key)) out = reader_.text(*value, at(key), max_length);
  }
  void integer(std::string_view key, int min, int max, int& out) const {
    if (const Json* value = get(key)) out = reader_.integer(*value, at(key), min, max);
  }
  void integer(std::string_view key, int min, int max, std::optional<int>& out) const {
    if (const Json* value = get(key)) out = reader_.integer(*value, at(key), min, max);
  }
  template <typename T, std::size_t N>
  void choice(std::string_view key, const std::array<std::string_view, N>& names,
              const std::array<T, N>& values, T& out) const {
    if (const Json* value = get(key)) out = reader_.choice(*value, at(key), names, values);
  }

  const Json& required(std::string_view key, std::string_view what) const {
    const Json* value = get(key);
    if (value == nullptr) reader_.fail(at(key), fmt::format("missing required field ({})", what));
    return *value;
  }

 private:
  const JsonReader& reader_;
  const Json& object_;
  std::string pointer_;
};

// "dash": [on, off, ...], at most kMaxDashes lengths > 0; [] is solid.
std::vector<double> read_dash(const JsonReader& reader, const Json& value,
                              const std::string& pointer) {
  if (!value.is_array()) {
    reader.fail(pointer, fmt::format("must be an array of at most {} dash lengths > 0 (got {})",
                                     kMaxDashes, value_text(value)));
  }
  if (value.size() > kMaxDashes) {
    reader.fail(pointer, fmt::format("must have at most {} dash lengths (got {})", kMaxDashes,
                                     value.size()));
  }
  std::vector<double> dash;
  for (std::size_t i = 0; i < value.size(); ++i) {
    dash.push_back(reader.number(value[i], element_pointer(pointer, i), kPositive));
  }
  return dash;
}

// "color", "width", "opacity", "dash" of a line, over `line`'s defaults.
void read_line(const Fields& fields, LineStyle& line) {
  fields.color("color", line.color);
  fields.number("width", kLineWidth, line.width);
  fields.number("opacity", kOpacity, line.opacity);
  if (const Json* dash = fields.get("dash")) {
    line.dash = read_dash(fields.reader(), *dash, fields.at("dash"));
  }
}

// "outline": {"color", "width", "opacity", "dash"} over LineStyle's defaults.
void read_outline(const Fields& fields, std::optional<LineStyle>& out) {
  const Json* value = fields.get("outline");
  if (value == nullptr) return;
  const std::string pointer = fields.at("outline");
  fields.reader().object(*value, pointer, "an outline");
  fields.reader().check_fields(*value, pointer, kLineFields);
  LineStyle line;
  read_line(Fields(fields.reader(), *value, pointer), line);
  out = line;
}

// "range": [from, to], from < to.
void read_range(const Fields& fields, std::optional<TimeRange>& out) {
  const Json* value = fields.get("range");
  if (value == nullptr) return;
  const std::string pointer = fields.at("range");
  if (!value->is_array() || value->size() != 2) {
    fields.reader().fail(pointer, "must be an array of two times [from, to] (got " +
                                      value_text(*value) + ")");
  }
  const double from = fields.reader().number((*value)[0], element_pointer(pointer, 0));
  const double to = fields.reader().number((*value)[1], element_pointer(pointer, 1));
  if (!(to > from)) {
    fields.reader().fail(
        element_pointer(pointer, 1),
        fmt::format("the end of a range must be greater than its start {} (got {})",
                    number_text(from), number_text(to)));
  }
  out = TimeRange{from, to};
}

void read_figure_samples(const Fields& fields, std::optional<int>& out) {
  fields.integer("samples", 2, kMaxFigureSamples, out);
}

// A layer's "options": those of the panel's method options a layer may change.
// The knot order is not one of them: it decides how the panel's keyframes
// were read (N41). Whether the layer's method reads each is checked where
// the layer is drawn (it depends on the panel's keyframes and chain).
MethodOptionsPatch read_options_patch(const Fields& fields, const Json& value) {
  const std::string pointer = fields.at("options");
  if (value.is_object() && JsonReader::member(value, "knots") != nullptr) {
    fields.reader().fail(pointer + "/knots", "the knot order belongs to the panel's keyframes; give it in the "
                                             "panel's or the scene's \"options\"");
  }
  MethodOptionsPatch patch;
  patch.values = fields.reader().options(value, pointer, MethodOptions{});
  for (const MethodOptionKey& key : kMethodOptionKeys) {
    if (JsonReader::member(value, std::string(key.name)) != nullptr) patch.given |= key.option;
  }
  return patch;
}

PatternLayer read_pattern(const Fields& fields) {
  PatternLayer layer;
  read_line(fields, layer.line);
  fields.boolean("extended", layer.extended);
  fields.boolean("coils", layer.coils);
  fields.boolean("heads", layer.heads);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  if (const Json* times = fields.get("times")) {
    const std::string pointer = fields.at("times");
    for (const std::string_view other : {std::string_view("samples"), std::string_view("range")}) {
      if (fields.get(other) != nullptr) {
        fields.reader().fail(pointer, fmt::format("draws the frames at exactly these times, and \"{}\" chooses "
                                                  "times too: give \"times\" or \"samples\" and \"range\"",
                                                  other));
      }
    }
    if (!times->is_array() || times->empty() || times->size() > static_cast<std::size_t>(kMaxFigureSamples)) {
      fields.reader().fail(pointer, fmt::format("must be an array of 1 to {} times (got {})", kMaxFigureSamples,
                                                value_text(*times)));
    }
    for (std::size_t i = 0; i < times->size(); ++i) {
      layer.times.push_back(fields.reader().number((*times)[i], element_pointer(pointer, i)));
    }
  }
  if (const Json* method = fields.get("method")) layer.method = fields.reader().method(*method, fields.at("method"));
  if (const Json* options = fields.get("options")) layer.options = read_options_patch(fields, *options);
  if (const Json* label = fields.get("label")) {
    layer.label = fields.reader().text(*label, fields.at("label"), kMaxTextLength);
  }
  fields.boolean("dots", layer.dots);
  if (layer.dots && layer.heads) {
    fields.reader().fail(fields.at("dots"), "draws each frame as the dot of its point p, and \"heads\" draws it "
                                            "as an arrow: choose one");
  }
  return layer;
}

KeyframesLayer read_keyframes_layer(const Fields& fields) {
  KeyframesLayer layer;
  if (const Json* colors = fields.get("colors")) {
    const std::string pointer = fields.at("colors");
    if (!colors->is_array() || colors->empty() || colors->size() > kMaxKeyframeColors) {
      fields.reader().fail(pointer, fmt::format("must be an array of 1 to {} colors (got {})",
                                                kMaxKeyframeColors, value_text(*colors)));
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
      fields.reader().fail(fields.at("curve"), "must be " + quoted_choices(names) + " (got " + value_text(*curve) + ")");
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
  layer.text = fields.reader().text(fields.required("text", "the text to draw"), fields.at("text"),
                                    kMaxTextLength);
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

LabelLayer read_label(const Fields& fields) {
  LabelLayer layer;
  layer.text = fields.reader().text(fields.required("text", "the text to draw"), fields.at("text"),
                                    kMaxTextLength);
  layer.at = fields.reader().point(fields.required("at", "the point [x, y] of the text"),
                                   fields.at("at"));
  fields.number("size", kTextSize, layer.size);
  fields.color("color", layer.color);
  return layer;
}

LegendLayer read_legend(const Fields& fields) {
  LegendLayer layer;
  fields.choice("corner", kCornerNames, kCorners, layer.corner);
  fields.number("size", kTextSize, layer.size);
  return layer;
}

// "at": a world point [x, y], or a corner of the panel ("top-left", ...).
void read_text_place(const Fields& fields, std::optional<Point>& at, LegendLayer::Corner& corner) {
  const Json* where = fields.get("at");
  if (where == nullptr) return;
  if (where->is_string()) {
    const std::string name = where->get<std::string>();
    const auto found = std::find(kCornerNames.begin(), kCornerNames.end(), name);
    if (found == kCornerNames.end()) {
      fields.reader().fail(fields.at("at"), fmt::format("must be a point [x, y] or a corner, {} (got {})",
                                                        quoted_choices(kCornerNames), value_text(*where)));
    }
    corner = kCorners[static_cast<std::size_t>(found - kCornerNames.begin())];
  } else {
    at = fields.reader().point(*where, fields.at("at"));
  }
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
  layer.method = fields.reader().method(fields.required("method", "the method compared with the panel's"),
                                        fields.at("method"));
  layer.method_name = std::string(info(layer.method).id);
  read_line(fields, layer.line);
  read_figure_samples(fields, layer.samples);
  read_text_place(fields, layer.at, layer.corner);
  fields.number("size", kTextSize, layer.size);
  return layer;
}

// "measures"; `poses`: in a pose scene (the names it may show differ,
// scene/measure_name.hpp).
MeasuresLayer read_measures(const Fields& fields, bool poses) {
  MeasuresLayer layer;
  const JsonReader& reader = fields.reader();
  const MeasureScene scene = poses ? MeasureScene::poses : MeasureScene::arrows;
  layer.show = default_measures(scene);
  if (const Json* show = fields.get("show")) {
    const std::string at = fields.at("show");
    if (!show->is_array() || show->empty() || show->size() > kMaxMeasures) {
      reader.fail(at, fmt::format("must be a list of 1 to {} measure names (got {})", kMaxMeasures,
                                  value_text(*show)));
    }
    layer.show.clear();
    for (std::size_t i = 0; i < show->size(); ++i) {
      const std::string item_at = element_pointer(at, i);
      auto parsed = parse_measure(reader.string((*show)[i], item_at), scene);
      if (const std::string* reason = std::get_if<std::string>(&parsed)) reader.fail(item_at, *reason);
      layer.show.push_back(std::move(std::get<MeasureName>(parsed)));
    }
  }
  read_text_place(fields, layer.at, layer.corner);
  fields.number("size", kTextSize, layer.size);
  fields.color("color", layer.color);
  return layer;
}

constexpr std::array<std::string_view, 2> kVectorKindNames = {"velocity", "acceleration"};
constexpr std::array<VectorKind, 2> kVectorKinds = {VectorKind::velocity, VectorKind::acceleration};
constexpr std::array<std::string_view, 3> kVectorAtNames = {"both", "p", "q"};
constexpr std::array<int, 3> kVectorAts = {3, 1, 2};  // bit 1: p, bit 2: q
constexpr std::array<std::string_view, 2> kAtPointNames = {"tail", "head"};
constexpr std::array<bool, 2> kTailAtPoint = {true, false};
constexpr std::array<std::string_view, 3> kCenterNames = {"global", "acceleration", "velocity"};
constexpr std::array<CenterKind, 3> kCenters = {CenterKind::global, CenterKind::acceleration,
                                                CenterKind::velocity};

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
      fields.reader().fail(pointer, "must be an array of 1 or 2 colors: [at p, at q] (got " +
                                        value_text(*colors) + ")");
    }
    layer.color_p = fields.reader().color((*colors)[0], element_pointer(pointer, 0));
    layer.color_q = colors->size() == 2 ? fields.reader().color((*colors)[1], element_pointer(pointer, 1))
                                        : layer.color_p;
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

// {"min": [x, y], "max": [x, y]} with min < max on both axes.
Box read_box(const Fields& box) {
  const JsonReader& reader = box.reader();
  const Point min = reader.point(box.required("min", "the corner [x, y] with the least x and y"),
                                 box.at("min"));
  const Point max = reader.point(box.required("max", "the corner [x, y] with the greatest x and y"),
                                 box.at("max"));
  const std::array<double, 2> low = {min.real(), min.imag()};
  const std::array<double, 2> high = {max.real(), max.imag()};
  for (std::size_t axis = 0; axis < 2; ++axis) {
    if (!(high[axis] > low[axis])) {
      const char* name = axis == 0 ? "x" : "y";
      reader.fail(element_pointer(box.at("max"), axis),
                  fmt::format("max {} must be greater than min {} {} (got {})", name, name,
                              number_text(low[axis]), number_text(high[axis])));
    }
  }
  return Box{min, max};
}

PropertyTableLayer read_property_table(const Fields& fields) {
  PropertyTableLayer layer;
  if (const Json* methods = fields.get("methods")) {
    const std::string at = fields.at("methods");
    if (!methods->is_array() || methods->empty()) {
      fields.reader().fail(at, "must be a non-empty array of method names (for example [\"P1\", \"P6\"])");
    }
    for (std::size_t i = 0; i < methods->size(); ++i) {
      const std::string item = at + "/" + std::to_string(i);
      const Method m = fields.reader().method((*methods)[i], item);
      if (info(m).keyframe_count != 3) {
        fields.reader().fail(item, fmt::format("{} takes {} keyframes; the properties of Sec. 4 are measured for the "
                                               "methods through three",
                                               info(m).id, info(m).keyframe_count));
      }
      layer.methods.push_back(m);
    }
  }
  fields.integer("configs", 1, kMaxTableConfigs, layer.configs);
  fields.integer("seed", 0, 2147483647, layer.seed);
  if (const Json* at = fields.get("at")) layer.at = fields.reader().point(*at, fields.at("at"));
  return layer;
}

std::vector<Color> read_colors(const Fields& fields, std::vector<Color> defaults);

// "plot"; `poses`: in a pose scene, where "of": "area" and its methods are read.
PlotLayer read_plot(const Fields& fields, bool poses) {
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
  fields.choice("of", kPlotOfNames, kPlotOfs, layer.of);
  if (layer.of == PlotOf::area && !poses) {
    fields.reader().fail(fields.at("of"), "\"area\" plots the area of a pose scene's shapes; an arrow scene's "
                                          "plot is of \"distance\"");
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

// One kind of layer: its "type", the fields it takes and how it is read. The
// two tables below are the only lists of layer kinds; every message, the
// schema test and the README derive theirs from them.
template <typename LayerType>
struct LayerKind {
  std::string_view type;
  std::span<const std::string_view> fields;
  LayerType (*read)(const Fields&);
  bool in_space = false;  // pose layers that 3D scenes draw too (render/space_drawing.hpp)
};

template <typename LayerType, std::size_t N>
std::vector<std::string_view> type_names(const std::array<LayerKind<LayerType>, N>& kinds) {
  std::vector<std::string_view> names;
  for (const auto& kind : kinds) names.push_back(kind.type);
  return names;
}

// Reads a layer of one of `kinds`; `others` are the kinds of the other kind
// of scene, named in the message when a layer of theirs is used here.
template <typename LayerType, std::size_t N, typename OtherType, std::size_t M>
LayerType read_layer_of(const JsonReader& reader, const Json& value, const std::string& pointer,
                        const std::array<LayerKind<LayerType>, N>& kinds,
                        const std::array<LayerKind<OtherType>, M>& others, std::string_view scene_kind) {
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
    reader.fail(fields.at(key), fmt::format("field \"{}\" is not used by a \"{}\" layer (its fields: {})",
                                            key, found->type, joined(known)));
  }
  reader.check_fields(value, pointer, known);
  return found->read(fields);
}

// "view": "auto", "shared" or {"min": [x, y], "max": [x, y]}.
void read_view(const JsonReader& reader, const Json& value, const std::string& pointer,
               Canvas& canvas) {
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
    reader.fail(pointer, "must be \"auto\", \"shared\" or a box {\"min\": [x, y], \"max\": [x, y]} "
                         "(got " + value_text(value) + ")");
  }
  reader.check_fields(value, pointer, kBoxFields);
  canvas.view = read_box(Fields(reader, value, pointer));
  canvas.shared_fit = false;
}

// "layers": an array of at most kMaxLayers layers, each read by `read_one`.
template <typename LayerType, typename ReadOne>
std::vector<LayerType> read_layer_array(const JsonReader& reader, const Json& value,
                                        const std::string& pointer, ReadOne read_one) {
  if (!value.is_array()) {
    reader.fail(pointer, "must be an array of layers (got " + value_text(value) + ")");
  }
  if (value.size() > static_cast<std::size_t>(kMaxLayers)) {
    reader.fail(pointer, fmt::format("must have at most {} layers (got {})", kMaxLayers,
                                     value.size()));
  }
  std::vector<LayerType> layers;
  for (std::size_t i = 0; i < value.size(); ++i) {
    layers.push_back(read_one(reader, value[i], element_pointer(pointer, i)));
  }
  return layers;
}

// ------------------------------------------------------------ pose layers

constexpr std::array<std::string_view, 10> kShapesFields = {
    "type", "color", "width", "opacity", "dash", "fill", "fill_opacity", "samples", "range", "lightness"};
constexpr std::array<std::string_view, 2> kLightnessNames = {"constant", "area"};
constexpr std::array<bool, 2> kLightnessByArea = {false, true};
constexpr std::array<std::string_view, 13> kFieldFields = {
    "type", "box", "columns", "rows", "scale", "color", "width", "opacity", "dash", "curves", "curve", "range",
    "fixed_point"};
constexpr std::array<std::string_view, 5> kPosesFields = {"type", "colors", "width",
                                                          "fill_opacity", "inserted"};
constexpr std::array<std::string_view, 8> kVelocitiesFields = {
    "type", "scale", "color", "width", "opacity", "dash", "samples", "range"};
constexpr std::array<std::string_view, 7> kPathsFields = {"type",  "samples", "range", "color",
                                                          "width", "opacity", "dash"};
constexpr std::array<std::string_view, 7> kExistenceFields = {
    "type", "columns", "rows", "fill", "exists_fill", "boundary", "trapezoid"};
constexpr std::array<std::string_view, 11> kPatchFields = {
    "type", "columns", "rows", "regular", "color", "width", "opacity", "dash", "fill", "fill_opacity",
    "corner"};
constexpr std::array<std::string_view, 6> kAraFields = {"type", "at", "size", "color", "digits", "grid"};
constexpr std::array<std::string_view, 13> kSweptFields = {
    "type", "edge", "samples", "range", "trace_samples", "instants", "segments", "ends", "envelope",
    "grazing", "claim_at", "size", "color"};
constexpr std::array<std::string_view, 12> kVersusFields = {
    "type", "method", "at", "power", "color", "width", "opacity", "dash", "fill", "fill_opacity", "samples",
    "range"};
constexpr std::array<std::string_view, 11> kSam3dExistenceFields = {
    "type", "steps", "subdivisions", "step", "color", "width", "opacity", "dash", "fill", "fill_opacity", "paper"};
constexpr Interval kSafeCurveStep{0.001, 0.1};

// A line style given as an object {"color", "width", "opacity", "dash"}.
void read_line_object(const Fields& fields, std::string_view key, LineStyle& line) {
  const Json* value = fields.get(key);
  if (value == nullptr) return;
  const std::string pointer = fields.at(key);
  fields.reader().object(*value, pointer, "a line style {\"color\", \"width\", \"opacity\", \"dash\"}");
  fields.reader().check_fields(*value, pointer, kLineFields);
  read_line(Fields(fields.reader(), *value, pointer), line);
}

std::vector<Color> read_colors(const Fields& fields, std::vector<Color> defaults) {
  const Json* colors = fields.get("colors");
  if (colors == nullptr) return defaults;
  const std::string pointer = fields.at("colors");
  if (!colors->is_array() || colors->empty() || colors->size() > kMaxKeyframeColors) {
    fields.reader().fail(pointer, fmt::format("must be an array of 1 to {} colors (got {})",
                                              kMaxKeyframeColors, value_text(*colors)));
  }
  std::vector<Color> result;
  for (std::size_t i = 0; i < colors->size(); ++i) {
    result.push_back(fields.reader().color((*colors)[i], element_pointer(pointer, i)));
  }
  return result;
}

// "shapes"; `poses`: in a pose scene, where "lightness": "area" is read.
ShapesLayer read_shapes_layer(const Fields& fields, bool poses) {
  ShapesLayer layer;
  read_line(fields, layer.line);
  fields.color("fill", layer.fill);
  fields.number("fill_opacity", kOpacity, layer.fill_opacity);
  read_figure_samples(fields, layer.samples);
  read_range(fields, layer.range);
  fields.choice("lightness", kLightnessNames, kLightnessByArea, layer.lightness_by_area);
  if (layer.lightness_by_area && !poses) {
    fields.reader().fail(fields.at("lightness"), "\"area\" shades a pose scene's shapes by their area; an arrow "
                                                 "scene's carry a similarity (use \"constant\")");
  }
  return layer;
}

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
    reader.fail(fields.at("rows"), fmt::format("columns x rows must be at most {} (got {} x {})",
                                               kMaxExistenceCells, layer.columns, layer.rows));
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

// A part of a "swept" layer: a line style object over `line`, or false to hide it.
void read_optional_line(const Fields& fields, std::string_view key, std::optional<LineStyle>& line) {
  const Json* value = fields.get(key);
  if (value == nullptr) return;
  if (value->is_boolean() && !value->get<bool>()) {
    line.reset();
    return;
  }
  if (!value->is_object()) {
    fields.reader().fail(fields.at(key),
                         "must be a line style {\"color\", \"width\", \"opacity\", \"dash\"} or false (got " +
                             value_text(*value) + ")");
  }
  LineStyle style = line.value_or(LineStyle{});
  read_line_object(fields, key, style);
  line = style;
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
  layer.method = read_pose_method(reader, fields.required("method", "the pose method to compare with"),
                                  fields.at("method"));
  if (const Json* at = fields.get("at")) {
    const std::string pointer = fields.at("at");
    if (!at->is_array() || at->empty() || at->size() > kMaxCompareTimes) {
      reader.fail(pointer, fmt::format("must be an array of 1 to {} times (got {})", kMaxCompareTimes,
                                       value_text(*at)));
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

// The layer kinds of keyframe (arrow) scenes, in the order messages, the
// schema and the README list them.
constexpr std::array<LayerKind<Layer>, 18> kArrowLayerKinds{{
    {"pattern", kPatternFields, [](const Fields& f) -> Layer { return read_pattern(f); }},
    {"keyframes", kKeyframesFields, [](const Fields& f) -> Layer { return read_keyframes_layer(f); }},
    {"trajectory", kTrajectoryFields, [](const Fields& f) -> Layer { return read_trajectory(f); }},
    {"stroke", kStrokeFields, [](const Fields& f) -> Layer { return read_stroke(f); }},
    {"banner", kBannerFields, [](const Fields& f) -> Layer { return read_banner(f); }},
    {"discrepancy", kDiscrepancyFields, [](const Fields& f) -> Layer { return read_discrepancy(f); }},
    {"label", kLabelFields, [](const Fields& f) -> Layer { return read_label(f); }},
    {"legend", kLegendFields, [](const Fields& f) -> Layer { return read_legend(f); }},
    {"plot", kPlotFields, [](const Fields& f) -> Layer { return read_plot(f, false); }},
    {"point-trajectory", kPointTrajectoryFields,
     [](const Fields& f) -> Layer { return read_point_trajectory(f); }},
    {"shapes", kShapesFields, [](const Fields& f) -> Layer { return read_shapes_layer(f, false); }},
    {"handle", kHandleFields, [](const Fields& f) -> Layer { return read_handle_layer(f); }},
    {"property-table", kPropertyTableFields, [](const Fields& f) -> Layer { return read_property_table(f); }},
    {"measures", kMeasuresFields, [](const Fields& f) -> Layer { return read_measures(f, false); }},
    {"vectors", kVectorsFields, [](const Fields& f) -> Layer { return read_vectors(f); }},
    {"fixed-points", kFixedPointsFields, [](const Fields& f) -> Layer { return read_fixed_points(f); }},
    {"guesses", kGuessesFields, [](const Fields& f) -> Layer { return read_guesses(f); }},
    {"compare", kCompareFields, [](const Fields& f) -> Layer { return read_compare(f); }},
}};

// The layer kinds of pose scenes.
constexpr std::array<LayerKind<PoseLayer>, 14> kPoseLayerKinds{{
    {"shapes", kShapesFields, [](const Fields& f) -> PoseLayer { return read_shapes_layer(f, true); }, true},
    {"poses", kPosesFields, [](const Fields& f) -> PoseLayer { return read_poses_layer(f); }, true},
    {"velocities", kVelocitiesFields, [](const Fields& f) -> PoseLayer { return read_velocities(f); }, true},
    {"paths", kPathsFields, [](const Fields& f) -> PoseLayer { return read_paths(f); }, true},
    {"existence", kExistenceFields, [](const Fields& f) -> PoseLayer { return read_existence(f); }},
    {"sam3d-existence", kSam3dExistenceFields,
     [](const Fields& f) -> PoseLayer { return read_sam3d_existence(f); }},
    {"label", kLabelFields, [](const Fields& f) -> PoseLayer { return read_label(f); }},
    {"patch", kPatchFields, [](const Fields& f) -> PoseLayer { return read_patch(f); }, true},
    {"plot", kPlotFields, [](const Fields& f) -> PoseLayer { return read_plot(f, true); }},
    {"ara", kAraFields, [](const Fields& f) -> PoseLayer { return read_ara(f); }},
    {"measures", kMeasuresFields, [](const Fields& f) -> PoseLayer { return read_measures(f, true); }},
    {"swept", kSweptFields, [](const Fields& f) -> PoseLayer { return read_swept(f); }},
    {"versus", kVersusFields, [](const Fields& f) -> PoseLayer { return read_versus(f); }},
    {"field", kFieldFields, [](const Fields& f) -> PoseLayer { return read_field(f); }},
}};

Layer read_layer(const JsonReader& reader, const Json& value, const std::string& pointer) {
  return read_layer_of(reader, value, pointer, kArrowLayerKinds, kPoseLayerKinds, "");
}

PoseLayer read_pose_layer(const JsonReader& reader, const Json& value, const std::string& pointer) {
  return read_layer_of(reader, value, pointer, kPoseLayerKinds, kArrowLayerKinds, " for a pose scene");
}

}  // namespace

template <typename LayerType, std::size_t N>
std::vector<LayerKindInfo> kind_infos(const std::array<LayerKind<LayerType>, N>& kinds) {
  std::vector<LayerKindInfo> infos;
  for (const auto& kind : kinds) infos.push_back({kind.type, kind.fields, kind.in_space});
  return infos;
}
std::vector<LayerKindInfo> arrow_layer_kinds() { return kind_infos(kArrowLayerKinds); }
std::vector<LayerKindInfo> pose_layer_kinds() { return kind_infos(kPoseLayerKinds); }

std::vector<PoseLayer> read_pose_layers(const JsonReader& reader, const Json& value,
                                        const std::string& pointer) {
  return read_layer_array<PoseLayer>(reader, value, pointer, read_pose_layer);
}

std::vector<PoseLayer> read_space_pose_layers(const JsonReader& reader, const Json& value,
                                              const std::string& pointer) {
  std::vector<PoseLayer> layers = read_pose_layers(reader, value, pointer);
  std::vector<std::string_view> space;
  for (const auto& kind : kPoseLayerKinds) {
    if (kind.in_space) space.push_back(kind.type);
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string type = value[i].at("type").get<std::string>();
    const auto kind = std::find_if(kPoseLayerKinds.begin(), kPoseLayerKinds.end(),
                                   [&](const auto& k) { return k.type == type; });
    if (kind != kPoseLayerKinds.end() && !kind->in_space) {
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

std::vector<Layer> read_layers(const JsonReader& reader, const Json& value,
                               const std::string& pointer) {
  return read_layer_array<Layer>(reader, value, pointer, read_layer);
}

}  // namespace pita::scene::detail
