// Reading the fields of a layer object (internal to src/scene/): the Fields
// view of an object being read, the bounds shared by many fields, and the
// readers of values several layer kinds take (lines, ranges, boxes, colors).
// Used by figure_reader.cpp, arrow_layer_reader.cpp and pose_layer_reader.cpp.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "scene/figure.hpp"
#include "scene/json_reader.hpp"

namespace pita::scene::detail {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();

// Bounds shared by several fields (schema/scene.schema.json says the same).
inline constexpr Interval kLineWidth{0.0, 100.0, /*min_open=*/true};
inline constexpr Interval kOpacity{0.0, 1.0};
inline constexpr Interval kPositive{0.0, kInfinity, /*min_open=*/true};
inline constexpr Interval kFraction{0.0, 0.45};  // margin, padding
inline constexpr Interval kTextSize{0.0, 200.0, /*min_open=*/true};

inline constexpr std::array<std::string_view, 2> kBoxFields = {"min", "max"};
inline constexpr std::array<std::string_view, 4> kLineFields = {"color", "width", "opacity", "dash"};
// A label's "place": where its text goes (LabelLayer::avoid_data).
inline constexpr std::array<std::string_view, 2> kLabelPlaceNames = {"at", "auto"};
inline constexpr std::array<bool, 2> kLabelPlaces = {false, true};

inline constexpr std::array<std::string_view, 4> kCornerNames = {"top-left", "top-right", "bottom-left",
                                                                 "bottom-right"};
inline constexpr std::array<LegendLayer::Corner, 4> kCorners = {
    LegendLayer::Corner::top_left, LegendLayer::Corner::top_right, LegendLayer::Corner::bottom_left,
    LegendLayer::Corner::bottom_right};

// An object being read: its members and where it is.
class Fields {
 public:
  Fields(const JsonReader& reader, const Json& object, std::string pointer)
      : reader_(reader), object_(object), pointer_(std::move(pointer)) {}

  const JsonReader& reader() const { return reader_; }
  const Json& object() const { return object_; }
  const std::string& pointer() const { return pointer_; }
  const Json* get(std::string_view key) const { return JsonReader::member(object_, std::string(key)); }
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
  void choice(std::string_view key, const std::array<std::string_view, N>& names, const std::array<T, N>& values,
              T& out) const {
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
std::vector<double> read_dash(const JsonReader& reader, const Json& value, const std::string& pointer);

// "color", "width", "opacity", "dash" of a line, over `line`'s defaults.
void read_line(const Fields& fields, LineStyle& line);

// "outline": {"color", "width", "opacity", "dash"} over LineStyle's defaults.
void read_outline(const Fields& fields, std::optional<LineStyle>& out);

// "range": [from, to], from < to.
void read_range(const Fields& fields, std::optional<TimeRange>& out);

void read_figure_samples(const Fields& fields, std::optional<int>& out);

// "times": exactly these frames (Fig. 5's D(1/4), Fig. 24's square at B),
// 1 to kMaxFigureSamples finite times, instead of "samples" and "range".
void read_frame_times(const Fields& fields, std::vector<double>& out);

// A layer's "options": those of the panel's method options a layer may change.
// The knot order is not one of them: it decides how the panel's keyframes
// were read (N41). Whether the layer's method reads each is checked where
// the layer is drawn (it depends on the panel's keyframes and chain).
MethodOptionsPatch read_options_patch(const Fields& fields, const Json& value);

// "at": a world point [x, y], or a corner of the panel ("top-left", ...).
void read_text_place(const Fields& fields, std::optional<Point>& at, LegendLayer::Corner& corner);

// {"min": [x, y], "max": [x, y]} with min < max on both axes.
Box read_box(const Fields& box);

// A line style given as an object {"color", "width", "opacity", "dash"}.
void read_line_object(const Fields& fields, std::string_view key, LineStyle& line);

std::vector<Color> read_colors(const Fields& fields, std::vector<Color> defaults);

// A part of a "swept" layer: a line style object over `line`, or false to hide it.
void read_optional_line(const Fields& fields, std::string_view key, std::optional<LineStyle>& line);

}  // namespace pita::scene::detail
