// The layer kinds of arrow scenes (src/scene/arrow_layer_reader.cpp): each
// kind's fields over its defaults. "guesses", "compare": test_arrow_layer_reader_guesses.cpp;
// "vectors", "fixed-points": test_arrow_layer_reader_vectors.cpp. The pointer and reason of
// every kind of error: the layers-* files of tests/data/bad/ (test_bad_scenes.cpp).
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "scene/color.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::expect_same_line;
using test::only_layer;
using test::p6_with;

Scene arrow_scene_with(const std::string& extra) { return parse_scene(p6_with(extra), "s.json"); }

std::vector<std::string> measure_texts(const std::vector<MeasureName>& show) {
  std::vector<std::string> out;
  for (const MeasureName& name : show) out.push_back(name.text);
  return out;
}

Color arrow_rgb(double r, double g, double b, double a = 1.0) { return Color{r, g, b, a}; }

TEST(Layers, Pattern) {
  const PatternLayer layer = only_layer<PatternLayer>(
      R"({"type": "pattern", "color": "#ff0000", "width": 2.5, "opacity": 0.5, "dash": [3, 1.5],
          "extended": true, "coils": true, "samples": 40, "range": [-0.5, 2]})");
  expect_same_line(layer.line, LineStyle{arrow_rgb(1, 0, 0), 2.5, 0.5, {3, 1.5}});
  EXPECT_TRUE(layer.extended);
  EXPECT_TRUE(layer.coils);
  EXPECT_EQ(layer.samples, 40);
  ASSERT_TRUE(layer.range.has_value());
  EXPECT_EQ(layer.range->from, -0.5);
  EXPECT_EQ(layer.range->to, 2);
}

TEST(Layers, PatternTimesMethodDots) {
  const PatternLayer layer =
      only_layer<PatternLayer>(R"({"type": "pattern", "times": [0.25, -1, 3], "method": "pa-po", "dots": true})");
  EXPECT_EQ(layer.times, (std::vector<double>{0.25, -1, 3}));
  ASSERT_TRUE(layer.method.has_value());
  EXPECT_EQ(*layer.method, Method::PaPo);
  EXPECT_TRUE(layer.dots);
  const PatternLayer plain = only_layer<PatternLayer>(R"({"type": "pattern"})");
  EXPECT_TRUE(plain.times.empty());
  EXPECT_FALSE(plain.method.has_value());
  EXPECT_FALSE(plain.dots);
}

TEST(Layers, Keyframes) {
  const KeyframesLayer layer = only_layer<KeyframesLayer>(
      R"({"type": "keyframes", "colors": ["black", "#0f0"], "width": 1, "opacity": 0.25,
          "winding": false, "spiral_center": "midpoint", "extended": true})");
  EXPECT_EQ(layer.colors, (std::vector<Color>{arrow_rgb(0, 0, 0), arrow_rgb(0, 1, 0)}));
  EXPECT_EQ(layer.width, 1);
  EXPECT_EQ(layer.opacity, 0.25);
  EXPECT_FALSE(layer.winding);
  EXPECT_EQ(layer.spiral_center, SpiralCenter::middle);
  EXPECT_TRUE(layer.extended);

  const KeyframesLayer plain = only_layer<KeyframesLayer>(R"({"type": "keyframes"})");
  EXPECT_EQ(plain.colors, KeyframesLayer{}.colors);
  EXPECT_EQ(plain.width, 2.0);
  EXPECT_TRUE(plain.winding);
  EXPECT_EQ(plain.spiral_center, SpiralCenter::start);
}

TEST(Layers, Trajectory) {
  const TrajectoryLayer layer = only_layer<TrajectoryLayer>(
      R"({"type": "trajectory", "point": "mid", "samples": 100000, "range": [0, 0.5],
          "color": "cyan", "width": 100, "opacity": 0, "dash": [1]})");
  EXPECT_EQ(layer.point, TrackedPoint::middle);
  EXPECT_EQ(layer.samples, kMaxTrajectorySamples);
  EXPECT_EQ(layer.range->to, 0.5);
  expect_same_line(layer.line, LineStyle{parse_color("cyan"), 100, 0, {1}});
  EXPECT_EQ(only_layer<TrajectoryLayer>(R"({"type": "trajectory", "point": "q"})").point, TrackedPoint::end);
  const TrajectoryLayer plain = only_layer<TrajectoryLayer>(R"({"type": "trajectory"})");
  EXPECT_EQ(plain.point, TrackedPoint::start);
  EXPECT_EQ(plain.samples, 512);
}

TEST(Layers, Stroke) {
  const StrokeLayer layer = only_layer<StrokeLayer>(
      R"({"type": "stroke", "fill": "#00000080", "opacity": 0.5,
          "outline": {"color": "red", "dash": [2, 2]}, "samples": 2, "range": [0.25, 0.75]})");
  EXPECT_EQ(layer.fill, arrow_rgb(0, 0, 0, 128 / 255.0));
  EXPECT_EQ(layer.opacity, 0.5);
  ASSERT_TRUE(layer.outline.has_value());
  expect_same_line(*layer.outline, LineStyle{parse_color("red"), 1.0, 1.0, {2, 2}});
  EXPECT_EQ(layer.samples, 2);
  EXPECT_EQ(layer.range->from, 0.25);
  EXPECT_FALSE(only_layer<StrokeLayer>(R"({"type": "stroke"})").outline.has_value());
  expect_same_line(*only_layer<StrokeLayer>(R"({"type": "stroke", "outline": {}})").outline, LineStyle{});
}

TEST(Layers, Banner) {
  const BannerLayer layer = only_layer<BannerLayer>(
      R"({"type": "banner", "text": "Été", "font": "Serif Italic", "fill": "orange",
          "opacity": 0.8, "outline": {"width": 0.5}, "padding": 0, "samples": 10000,
          "range": [0, 1]})");
  EXPECT_EQ(layer.text, "Été");
  EXPECT_EQ(layer.font, "Serif Italic");
  EXPECT_EQ(layer.fill, parse_color("orange"));
  EXPECT_EQ(layer.opacity, 0.8);
  EXPECT_EQ(layer.outline->width, 0.5);
  EXPECT_EQ(layer.padding, 0);
  EXPECT_EQ(layer.samples, kMaxFigureSamples);
  const BannerLayer plain = only_layer<BannerLayer>(R"({"type": "banner", "text": "x"})");
  EXPECT_EQ(plain.font, "Sans Bold");
  EXPECT_EQ(plain.padding, 0.1);
  EXPECT_FALSE(plain.outline.has_value());
  // The length counts characters, not bytes: 1000 two-byte characters fit.
  std::string long_text;
  for (std::size_t i = 0; i < kMaxTextLength; ++i) long_text += "é";
  EXPECT_EQ(only_layer<BannerLayer>(R"({"type": "banner", "text": ")" + long_text + "\"}").text, long_text);
}

TEST(Layers, Discrepancy) {
  const DiscrepancyLayer layer = only_layer<DiscrepancyLayer>(
      R"({"type": "discrepancy", "predictor": "pita", "method": "lo-pe", "scale": 0.5,
          "color": "green", "width": 0.1, "opacity": 1, "dash": [5], "fill": "yellow",
          "samples": 12})");
  EXPECT_EQ(layer.predictor, Predictor::pita);
  EXPECT_EQ(layer.method, Method::P8);
  EXPECT_EQ(layer.scale, 0.5);
  expect_same_line(layer.line, LineStyle{parse_color("green"), 0.1, 1, {5}});
  EXPECT_EQ(layer.fill, parse_color("yellow"));
  EXPECT_EQ(layer.samples, 12);
  const DiscrepancyLayer plain = only_layer<DiscrepancyLayer>(R"({"type": "discrepancy", "predictor": "pita"})");
  EXPECT_FALSE(plain.method.has_value());  // the panel's method
  EXPECT_FALSE(plain.fill.has_value());
  EXPECT_EQ(plain.scale, 30);
  EXPECT_EQ(only_layer<DiscrepancyLayer>(R"({"type": "discrepancy", "predictor": "average"})").predictor,
            Predictor::average);
  EXPECT_EQ(only_layer<DiscrepancyLayer>(R"({"type": "discrepancy"})").predictor, Predictor::previous);
}

TEST(Layers, LabelAndLegend) {
  const LabelLayer label =
      only_layer<LabelLayer>(R"({"type": "label", "text": "A", "at": [1.5, -2], "size": 200, "color": "#808080"})");
  EXPECT_EQ(label.text, "A");
  EXPECT_EQ(label.at, make_point(1.5, -2));
  EXPECT_EQ(label.size, 200);
  EXPECT_EQ(label.color, parse_color("gray"));
  EXPECT_EQ(only_layer<LabelLayer>(R"({"type": "label", "text": "B", "at": [0, 0]})").size, 12);

  const LegendLayer legend = only_layer<LegendLayer>(R"({"type": "legend", "corner": "bottom-left", "size": 9})");
  EXPECT_EQ(legend.corner, LegendLayer::Corner::bottom_left);
  EXPECT_EQ(legend.size, 9);
  const LegendLayer plain = only_layer<LegendLayer>(R"({"type": "legend"})");
  EXPECT_EQ(plain.corner, LegendLayer::Corner::top_left);
  EXPECT_EQ(plain.size, 11);
  EXPECT_EQ(only_layer<LegendLayer>(R"({"type": "legend", "corner": "top-right"})").corner,
            LegendLayer::Corner::top_right);
  EXPECT_EQ(only_layer<LegendLayer>(R"({"type": "legend", "corner": "bottom-right"})").corner,
            LegendLayer::Corner::bottom_right);
}

TEST(Layers, Measures) {
  const MeasuresLayer defaults = only_layer<MeasuresLayer>(R"({"type": "measures"})");
  EXPECT_EQ(measure_texts(defaults.show), (std::vector<std::string>{"overreaction", "pop"}));
  EXPECT_FALSE(defaults.at.has_value());
  EXPECT_EQ(defaults.corner, LegendLayer::Corner::bottom_left);
  const MeasuresLayer placed = only_layer<MeasuresLayer>(
      R"({"type": "measures", "show": ["pop", "gain:B.q", "jump:K27.p.x"], "at": [1, 2], "size": 9, "color": "#0000ff"})");
  EXPECT_EQ(measure_texts(placed.show), (std::vector<std::string>{"pop", "gain:B.q", "jump:K27.p.x"}));
  EXPECT_EQ(placed.show[1].kind, MeasureKind::gain);
  EXPECT_EQ(placed.show[1].parameter, "B.q");
  ASSERT_TRUE(placed.at.has_value());
  EXPECT_EQ(*placed.at, (Point{1.0, 2.0}));
  EXPECT_EQ(placed.size, 9.0);
  EXPECT_EQ(placed.color, arrow_rgb(0, 0, 1));
  EXPECT_EQ(only_layer<MeasuresLayer>(R"({"type": "measures", "at": "top-right"})").corner,
            LegendLayer::Corner::top_right);
  // Each name is parsed by scene/measure_name.cpp (tests/scene/test_measure_name.cpp);
  // a refused one is the reader's error at its pointer.
  try {
    arrow_scene_with(R"(, "layers": [{"type": "measures", "show": ["pop", "ara"]}])");
    ADD_FAILURE() << "an arrow scene showing \"ara\" was accepted";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/layers/0/show/1");
    EXPECT_NE(std::string(error.what()).find("pose scenes only"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace pita::scene
