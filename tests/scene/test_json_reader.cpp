// The checking JSON reader of the scene reader (src/scene/json_reader.cpp):
// JSON Pointers and value texts of messages, the checks of numbers, integers,
// texts, points, fields and choices. Each error test asserts the pointer and
// the whole reason (keyframes: test_keyframe_reader.cpp).
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "scene/json_reader.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::p6_with;
using test::p6_with_middle;

using detail::Interval;
using detail::Json;
using detail::JsonReader;
using test::error_of;

constexpr double kInf = std::numeric_limits<double>::infinity();

using test::failure;

using test::kReader;

// ------------------------------------------------------------ messages

TEST(JsonPointer, EscapesTildeAndSlashInMemberNames) {
  EXPECT_EQ(detail::member_pointer("", "keyframes"), "/keyframes");
  EXPECT_EQ(detail::member_pointer("/panels/0", "a~b/c"), "/panels/0/a~0b~1c");
  EXPECT_EQ(detail::member_pointer("/x", "~1"), "/x/~01");
  EXPECT_EQ(detail::element_pointer("/keyframes", 12), "/keyframes/12");
}

TEST(NumberText, IsTheShortestFormThatReadsBack) {
  EXPECT_EQ(detail::number_text(-2.0), "-2");
  EXPECT_EQ(detail::number_text(0.5), "0.5");
  EXPECT_EQ(detail::number_text(0.1), "0.1");
  EXPECT_EQ(detail::number_text(1e300), "1e+300");
  EXPECT_EQ(detail::number_text(kInf), "inf");
  EXPECT_EQ(std::stod(detail::number_text(1.0 / 3.0)), 1.0 / 3.0);
}

TEST(ValueText, NamesTheKindAndCutsLongValues) {
  EXPECT_EQ(detail::value_text(Json(3)), "3");
  EXPECT_EQ(detail::value_text(Json(2.5)), "2.5");
  EXPECT_EQ(detail::value_text(Json(nullptr)), "null");
  EXPECT_EQ(detail::value_text(Json(true)), "true");
  EXPECT_EQ(detail::value_text(Json("abc")), "string \"abc\"");
  EXPECT_EQ(detail::value_text(Json::parse("[1, 2, 3]")), "array [1,2,3]");
  EXPECT_EQ(detail::value_text(Json::parse(R"({"a": [1]})")), "object {\"a\":[1]}");
  // 40 characters at most after the kind: 37 and "...".
  const std::string long_text = detail::value_text(Json(std::string(100, 'x')));
  EXPECT_EQ(long_text, "string \"" + std::string(36, 'x') + "...");
  // Deep nesting is not descended.
  EXPECT_EQ(detail::value_text(Json::parse("[[[[[1]]]]]")), "array [[[[...]]]]");
}

TEST(MethodReasons, SayHowManyKeyframesTheMethodTakes) {
  EXPECT_EQ(detail::keyframe_count_reason(Method::P6, 0),
            "method P6 (La-LP) takes at least 3 keyframes (got 0); more are chained (\"chain\")");
  EXPECT_EQ(detail::keyframe_count_reason(Method::SMA, 1),
            "method SMA takes at least 2 keyframes (got 1); more are chained (\"chain\")");
  // A pose method in an arrow scene says what to give instead.
  EXPECT_EQ(detail::unknown_scene_method_reason("SAM", is_method_of<Method>),
            "method SAM interpolates poses, and this scene has keyframes (arrows): give it "
            "\"poses\" instead, or an arrow method such as P6");
  // An arrow method in a pose scene, the other way round.
  EXPECT_EQ(detail::unknown_scene_method_reason("P6", is_method_of<PoseMethod>),
            "method P6 interpolates arrows, and this is a pose scene: give it \"keyframes\" instead, or a pose "
            "method such as SAM");
  const std::array<std::string_view, 3> names = {"a", "b", "c"};
  EXPECT_EQ(detail::joined(names), "a, b, c");
}

// ------------------------------------------------------------ reader

TEST(JsonReader, NumbersMustBeFiniteAndInTheirInterval) {
  EXPECT_EQ(kReader.number(Json(1.25), "/n"), 1.25);
  EXPECT_EQ(failure([] { kReader.number(Json("1"), "/n"); }), "/n: must be a number (got string \"1\")");
  EXPECT_EQ(failure([] {
              kReader.number(Json(2.0), "/n", Interval{0.0, 1.0});
            }),
            "/n: must be between 0 and 1 (got 2)");
  EXPECT_EQ(failure([] { kReader.number(Json(0.0), "/n", Interval{0.0, kInf, true}); }), "/n: must be > 0 (got 0)");
  EXPECT_EQ(failure([] {
              kReader.number(Json(5.0), "/n", Interval{-kInf, 5.0, false, true});
            }),
            "/n: must be < 5 (got 5)");
  EXPECT_EQ(failure([] {
              kReader.number(Json(0.0), "/n", Interval{0.0, 1.0, true, false});
            }),
            "/n: must be > 0 and <= 1 (got 0)");
  EXPECT_EQ(kReader.number(Json(1.0), "/n", Interval{0.0, 1.0}), 1.0);  // closed end
}

TEST(JsonReader, IntegersHaveNoFractionalPart) {
  EXPECT_EQ(kReader.integer(Json(3.0), "/i"), 3.0);
  EXPECT_EQ(kReader.integer(Json(4), "/i", 1, 5), 4);
  EXPECT_EQ(failure([] { kReader.integer(Json(2.5), "/i"); }), "/i: must be an integer (got 2.5)");
  EXPECT_EQ(failure([] { kReader.integer(Json(7), "/i", 1, 5); }), "/i: must be an integer between 1 and 5 (got 7)");
}

TEST(JsonReader, TextsAreCountedInCharactersNotBytes) {
  EXPECT_EQ(kReader.text(Json("h\u00e9llo"), "/s", 5), "h\u00e9llo");  // 6 bytes, 5 characters
  EXPECT_EQ(failure([] { kReader.text(Json("h\u00e9llo!"), "/s", 5); }),
            "/s: must be at most 5 characters long (got 6)");
  EXPECT_EQ(failure([] { kReader.text(Json(""), "/s", 5); }), "/s: must not be empty");
  EXPECT_EQ(failure([] { kReader.boolean(Json(1), "/b"); }), "/b: must be true or false (got 1)");
}

TEST(JsonReader, PointsAreTwoNumbers) {
  EXPECT_EQ(kReader.point(Json::parse("[1, -2.5]"), "/p"), make_point(1.0, -2.5));
  EXPECT_EQ(failure([] { kReader.point(Json::parse("[1]"), "/p"); }),
            "/p: must be an array of two numbers [x, y] (got array [1])");
  EXPECT_EQ(failure([] { kReader.point(Json::parse(R"([1, "2"])"), "/p"); }),
            "/p/1: must be a number (got string \"2\")");
}

TEST(JsonReader, UnknownFieldsAreNamedWithTheClosestKnownOnes) {
  const std::array<std::string_view, 3> known = {"t", "color", "width"};
  const std::string misspelt =
      failure([&] { kReader.check_fields(Json::parse(R"({"t": 0, "colour": 1})"), "/x", known); });
  EXPECT_EQ(misspelt.rfind("/x/colour: unknown field \"colour\"; did you mean", 0), 0u) << misspelt;
  EXPECT_NE(misspelt.find("\"color\""), std::string::npos) << misspelt;
  EXPECT_EQ(failure([&] { kReader.check_fields(Json::parse(R"({"zzzzzz": 0})"), "", known); }),
            "/zzzzzz: unknown field \"zzzzzz\"; known fields: t, color, width");
  EXPECT_EQ(failure([&] { kReader.check_fields(Json::parse(R"({"width": 0, "t": 1})"), "/x", known); }), "(no error)");
}

TEST(JsonReader, ChoicesMapNamesToValues) {
  const std::array<std::string_view, 2> names = {"start", "midpoint"};
  const std::array<int, 2> values = {10, 20};
  EXPECT_EQ(kReader.choice(Json("midpoint"), "/c", names, values), 20);
  const std::string wrong = failure([&] { kReader.choice(Json("middle"), "/c", names, values); });
  EXPECT_EQ(wrong.rfind("/c: must be ", 0), 0u) << wrong;
  EXPECT_NE(wrong.find("\"start\""), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("\"midpoint\""), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("(got string \"middle\")"), std::string::npos) << wrong;
}

TEST(JsonReader, OptionsReplaceOnlyTheFieldsGiven) {
  MethodOptions base;
  base.anchor = Anchor::midpoint;
  const MethodOptions read = kReader.options(Json::parse(R"({"path_mean": "harmonic"})"), "/options", base);
  EXPECT_EQ(read.anchor, Anchor::midpoint);
  EXPECT_EQ(read.path_mean, MeanKind::harmonic);
  EXPECT_EQ(read.magnitude_mean, base.magnitude_mean);
}

}  // namespace
}  // namespace pita::scene
