#include "scene/layer_fields.hpp"

#include <algorithm>

#include "core/methods.hpp"

namespace pita::scene::detail {

// "dash": [on, off, ...], at most kMaxDashes lengths > 0; [] is solid.
std::vector<double> read_dash(const JsonReader& reader, const Json& value, const std::string& pointer) {
  if (!value.is_array()) {
    reader.fail(pointer,
                fmt::format("must be an array of at most {} dash lengths > 0 (got {})", kMaxDashes, value_text(value)));
  }
  if (value.size() > kMaxDashes) {
    reader.fail(pointer, fmt::format("must have at most {} dash lengths (got {})", kMaxDashes, value.size()));
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

// "times": exactly these frames, instead of "samples" and "range".
void read_frame_times(const Fields& fields, std::vector<double>& out) {
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
      fields.reader().fail(
          pointer, fmt::format("must be an array of 1 to {} times (got {})", kMaxFigureSamples, value_text(*times)));
    }
    for (std::size_t i = 0; i < times->size(); ++i) {
      out.push_back(fields.reader().number((*times)[i], element_pointer(pointer, i)));
    }
  }
}

// "range": [from, to], from < to.
void read_range(const Fields& fields, std::optional<TimeRange>& out) {
  const Json* value = fields.get("range");
  if (value == nullptr) return;
  const std::string pointer = fields.at("range");
  if (!value->is_array() || value->size() != 2) {
    fields.reader().fail(pointer, "must be an array of two times [from, to] (got " + value_text(*value) + ")");
  }
  const double from = fields.reader().number((*value)[0], element_pointer(pointer, 0));
  const double to = fields.reader().number((*value)[1], element_pointer(pointer, 1));
  if (!(to > from)) {
    fields.reader().fail(element_pointer(pointer, 1),
                         fmt::format("the end of a range must be greater than its start {} (got {})", number_text(from),
                                     number_text(to)));
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
    fields.reader().fail(pointer + "/knots",
                         "the knot order belongs to the panel's keyframes; give it in the "
                         "panel's or the scene's \"options\"");
  }
  MethodOptionsPatch patch;
  patch.values = fields.reader().options(value, pointer, MethodOptions{});
  for (const MethodOptionKey& key : kMethodOptionKeys) {
    if (JsonReader::member(value, std::string(key.name)) != nullptr) patch.given |= key.option;
  }
  return patch;
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

// {"min": [x, y], "max": [x, y]} with min < max on both axes.
Box read_box(const Fields& box) {
  const JsonReader& reader = box.reader();
  const Point min = reader.point(box.required("min", "the corner [x, y] with the least x and y"), box.at("min"));
  const Point max = reader.point(box.required("max", "the corner [x, y] with the greatest x and y"), box.at("max"));
  const std::array<double, 2> low = {min.real(), min.imag()};
  const std::array<double, 2> high = {max.real(), max.imag()};
  for (std::size_t axis = 0; axis < 2; ++axis) {
    if (!(high[axis] > low[axis])) {
      const char* name = axis == 0 ? "x" : "y";
      reader.fail(element_pointer(box.at("max"), axis),
                  fmt::format("max {} must be greater than min {} {} (got {})", name, name, number_text(low[axis]),
                              number_text(high[axis])));
    }
  }
  return Box{min, max};
}

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
    fields.reader().fail(
        pointer, fmt::format("must be an array of 1 to {} colors (got {})", kMaxKeyframeColors, value_text(*colors)));
  }
  std::vector<Color> result;
  for (std::size_t i = 0; i < colors->size(); ++i) {
    result.push_back(fields.reader().color((*colors)[i], element_pointer(pointer, i)));
  }
  return result;
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
    fields.reader().fail(
        fields.at(key),
        "must be a line style {\"color\", \"width\", \"opacity\", \"dash\"} or false (got " + value_text(*value) + ")");
  }
  LineStyle style = line.value_or(LineStyle{});
  read_line_object(fields, key, style);
  line = style;
}

}  // namespace pita::scene::detail
