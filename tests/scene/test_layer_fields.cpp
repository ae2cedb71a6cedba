// The fields several layer kinds share (src/scene/layer_fields.cpp): line
// styles, ranges, boxes, dashes and colours, read over their defaults, and
// their errors with the field's pointer.
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "scene/color.hpp"
#include "scene/layer_fields.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::expect_same_line;
using test::failure;
using test::kReader;
using test::only_layer;
using test::p6_with;

// The object `text` as the fields of a layer at /layers/0.
struct FieldsOf {
  explicit FieldsOf(const std::string& text) : json(detail::Json::parse(text)) {}
  detail::Fields fields() const { return detail::Fields(kReader, json, "/layers/0"); }
  detail::Json json;  // the type Fields refers to (no converted copy)
};

TEST(Layers, LineFieldsOverrideOnlyWhatIsGiven) {
  const PatternLayer pattern = only_layer<PatternLayer>(R"({"type": "pattern", "width": 3})");
  LineStyle expected = PatternLayer{}.line;
  expected.width = 3;
  expect_same_line(pattern.line, expected);
  EXPECT_FALSE(pattern.samples.has_value());
  EXPECT_FALSE(pattern.range.has_value());
  EXPECT_FALSE(pattern.extended);
  EXPECT_FALSE(pattern.coils);

  const TrajectoryLayer trajectory = only_layer<TrajectoryLayer>(R"({"type": "trajectory", "color": "blue"})");
  expected = TrajectoryLayer{}.line;
  expected.color = parse_color("blue");
  expect_same_line(trajectory.line, expected);

  const DiscrepancyLayer discrepancy = only_layer<DiscrepancyLayer>(R"({"type": "discrepancy", "dash": []})");
  expect_same_line(discrepancy.line, DiscrepancyLayer{}.line);
}

TEST(LayerFields, RangeIsTwoIncreasingTimes) {
  std::optional<TimeRange> range;
  detail::read_range(FieldsOf(R"({"range": [0.25, 2]})").fields(), range);
  ASSERT_TRUE(range.has_value());
  EXPECT_EQ(range->from, 0.25);
  EXPECT_EQ(range->to, 2.0);
  std::optional<TimeRange> untouched;
  detail::read_range(FieldsOf("{}").fields(), untouched);
  EXPECT_FALSE(untouched.has_value());
  EXPECT_EQ(failure([] {
              std::optional<TimeRange> out;
              detail::read_range(FieldsOf(R"({"range": [1, 1]})").fields(), out);
            }),
            "/layers/0/range/1: the end of a range must be greater than its start 1 (got 1)");
  EXPECT_EQ(failure([] {
              std::optional<TimeRange> out;
              detail::read_range(FieldsOf(R"({"range": [1]})").fields(), out);
            }),
            "/layers/0/range: must be an array of two times [from, to] (got array [1])");
}

TEST(LayerFields, BoxCornersIncreaseOnBothAxes) {
  const Box box = detail::read_box(FieldsOf(R"({"min": [-1, 0], "max": [2, 3]})").fields());
  EXPECT_EQ(box.min, Point(-1.0, 0.0));
  EXPECT_EQ(box.max, Point(2.0, 3.0));
  EXPECT_EQ(failure([] { detail::read_box(FieldsOf(R"({"min": [0, 5], "max": [1, 5]})").fields()); }),
            "/layers/0/max/1: max y must be greater than min y 5 (got 5)");
}

TEST(LayerFields, DashLengthsArePositiveAndFew) {
  LineStyle line;
  detail::read_line(FieldsOf(R"({"dash": [2, 0.5], "opacity": 0.25})").fields(), line);
  expect_same_line(line, LineStyle{Color{}, 1.0, 0.25, {2.0, 0.5}});
  EXPECT_EQ(failure([] {
              LineStyle out;
              detail::read_line(FieldsOf(R"({"dash": [1, 0]})").fields(), out);
            }).substr(0, 19),
            "/layers/0/dash/1: m");
  std::string many = "[1";
  for (std::size_t i = 1; i <= kMaxDashes; ++i) many += ", 1";
  EXPECT_EQ(failure([&] {
              LineStyle out;
              detail::read_line(FieldsOf(R"({"dash": )" + many + "]}").fields(), out);
            }),
            "/layers/0/dash: must have at most 16 dash lengths (got 17)");
}

TEST(LayerFields, ColorsReplaceTheDefaultsOnlyWhenGiven) {
  const std::vector<Color> defaults = {parse_color("red")};
  EXPECT_EQ(detail::read_colors(FieldsOf("{}").fields(), defaults), defaults);
  const std::vector<Color> given =
      detail::read_colors(FieldsOf(R"({"colors": ["blue", "#00ff00"]})").fields(), defaults);
  ASSERT_EQ(given.size(), 2U);
  EXPECT_EQ(given[0], parse_color("blue"));
  EXPECT_EQ(given[1], (Color{0.0, 1.0, 0.0, 1.0}));
  EXPECT_EQ(failure([&] { detail::read_colors(FieldsOf(R"({"colors": []})").fields(), defaults); }),
            "/layers/0/colors: must be an array of 1 to 16 colors (got array [])");
}

TEST(LayerFields, OptionalLineIsHiddenByFalseAndRestyledByAnObject) {
  std::optional<LineStyle> line = LineStyle{parse_color("red"), 2.0, 1.0, {}};
  detail::read_optional_line(FieldsOf(R"({"ends": {"width": 4}})").fields(), "ends", line);
  ASSERT_TRUE(line.has_value());
  expect_same_line(*line, LineStyle{parse_color("red"), 4.0, 1.0, {}});  // unset members keep theirs
  detail::read_optional_line(FieldsOf(R"({"ends": false})").fields(), "ends", line);
  EXPECT_FALSE(line.has_value());
}

// A layer's "options" (docs/paper-notes.md N54): what it gives, over the
// panel's options; the knot order is the panel's alone.
TEST(LayerFields, OptionsPatchRecordsWhatItGives) {
  const FieldsOf object(R"({"options": {"path_mean": "arithmetic"}})");
  const MethodOptionsPatch patch = detail::read_options_patch(object.fields(), object.json.at("options"));
  EXPECT_EQ(patch.given, static_cast<unsigned>(kPathMeanOption));
  MethodOptions base;
  base.anchor = Anchor::midpoint;
  const MethodOptions over = patch.over(base);
  EXPECT_EQ(over.path_mean, MeanKind::arithmetic);
  EXPECT_EQ(over.anchor, Anchor::midpoint);  // not given: the panel's
  EXPECT_EQ(failure([] {
              const FieldsOf knots(R"({"options": {"knots": "as-given"}})");
              detail::read_options_patch(knots.fields(), knots.json.at("options"));
            }).substr(0, 42),
            "/layers/0/options/knots: the knot order be");
}

}  // namespace
}  // namespace pita::scene
