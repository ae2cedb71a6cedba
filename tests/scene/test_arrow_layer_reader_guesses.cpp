// The "guesses" and "compare" layers of src/scene/arrow_layer_reader.cpp (PITA
// Figs. 16, 18, B.30; docs/paper-notes.md N53, N54): defaults, fields and
// errors with their pointers.
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "scene/color.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::error_of;
using test::only_layer;
using test::p6_with;

TEST(GuessesLayerReader, NamesAndColoursByPositionByDefault) {
  const GuessesLayer layer = only_layer<GuessesLayer>(
      R"({"type": "guesses", "guesses": [{"t": 0.25, "p": [0, 0], "q": [1, 0]}, {"t": 0.75, "p": [1, 1], "m": 2, "w": 3.5}]})");
  ASSERT_EQ(layer.guesses.size(), 2U);
  EXPECT_EQ(layer.guesses[0].name, "G1");
  EXPECT_EQ(layer.guesses[1].name, "G2");
  EXPECT_EQ(layer.guesses[0].t, 0.25);
  EXPECT_EQ(layer.guesses[0].arrow.q(), Point(1.0, 0.0));
  EXPECT_EQ(layer.guesses[1].arrow.m, 2.0);
  EXPECT_EQ(layer.guesses[1].arrow.w, 3.5);  // as given, not reduced
  EXPECT_NE(layer.guesses[0].color, layer.guesses[1].color);
  ASSERT_EQ(layer.show.size(), 1U);
  EXPECT_EQ(layer.show[0], GuessMeasure::discrepancy);
  EXPECT_FALSE(layer.at);
  EXPECT_EQ(layer.corner, LegendLayer::Corner::bottom_left);
}

TEST(GuessesLayerReader, EveryField) {
  const GuessesLayer layer = only_layer<GuessesLayer>(
      R"({"type": "guesses", "guesses": [{"t": 2, "p": [0, 0], "q": [1, 0], "name": "L", "color": "brown"}],
          "show": ["distance", "discrepancy"], "width": 3, "frame_color": "red", "at": [1, 2], "size": 14,
          "color": "blue"})");
  EXPECT_EQ(layer.guesses[0].name, "L");
  EXPECT_EQ(layer.guesses[0].color, parse_color("brown"));
  ASSERT_EQ(layer.show.size(), 2U);
  EXPECT_EQ(layer.show[0], GuessMeasure::distance);
  EXPECT_EQ(layer.width, 3.0);
  EXPECT_EQ(layer.frame_color, parse_color("red"));
  ASSERT_TRUE(layer.at);
  EXPECT_EQ(*layer.at, Point(1.0, 2.0));
  EXPECT_EQ(layer.size, 14.0);
  EXPECT_EQ(layer.color, parse_color("blue"));
}

TEST(GuessesLayerReader, ErrorsNameTheField) {
  EXPECT_NE(error_of(p6_with(R"(, "layers": [{"type": "guesses"}])")).find("/layers/0/guesses: missing required field"),
            std::string::npos);
  EXPECT_NE(error_of(p6_with(R"(, "layers": [{"type": "guesses", "guesses": []}])"))
                .find("/layers/0/guesses: must be an array"),
            std::string::npos);
  EXPECT_NE(error_of(p6_with(R"(, "layers": [{"type": "guesses", "guesses": [{"p": [0, 0], "q": [1, 0]}]}])"))
                .find("/layers/0/guesses/0/t: missing required field"),
            std::string::npos);
  EXPECT_NE(error_of(p6_with(R"(, "layers": [{"type": "guesses", "guesses": [{"t": 0, "p": [0, 0], "q": [0, 0]}]}])"))
                .find("/layers/0/guesses/0/q"),
            std::string::npos);
  EXPECT_NE(
      error_of(
          p6_with(R"(, "layers": [{"type": "guesses", "guesses": [{"t": 0, "p": [0, 0], "q": [1, 0], "nmae": "L"}]}])"))
          .find("/layers/0/guesses/0/nmae"),
      std::string::npos);
  EXPECT_NE(
      error_of(
          p6_with(
              R"(, "layers": [{"type": "guesses", "guesses": [{"t": 0, "p": [0, 0], "q": [1, 0]}], "show": ["error"]}])"))
          .find("/layers/0/show/0"),
      std::string::npos);
}

TEST(CompareLayerReader, MethodRequiredAndDashedOrangeByDefault) {
  const CompareLayer layer = only_layer<CompareLayer>(R"({"type": "compare", "method": "p10"})");
  EXPECT_EQ(layer.method, Method::P10);
  EXPECT_EQ(layer.method_name, "P10");
  EXPECT_FALSE(layer.line.dash.empty());
  const CompareLayer set = only_layer<CompareLayer>(
      R"({"type": "compare", "method": "P1", "color": "red", "dash": [], "samples": 5, "at": "top-right", "size": 9})");
  EXPECT_EQ(set.method, Method::P1);
  EXPECT_TRUE(set.line.dash.empty());
  EXPECT_EQ(set.samples, 5);
  EXPECT_EQ(set.corner, LegendLayer::Corner::top_right);
  EXPECT_NE(error_of(p6_with(R"(, "layers": [{"type": "compare"}])")).find("/layers/0/method: missing required field"),
            std::string::npos);
  EXPECT_NE(error_of(p6_with(R"(, "layers": [{"type": "compare", "method": "P99"}])")).find("/layers/0/method"),
            std::string::npos);
}

}  // namespace
}  // namespace pita::scene
