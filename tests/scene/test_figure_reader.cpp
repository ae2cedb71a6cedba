// The figure part of a scene (src/scene/figure_reader.cpp and the panels of
// src/scene/scene.cpp): title, canvas, layers and panels, and their defaults.
// The pointer and reason of every kind of error: the canvas-*, layers-*,
// panels-* and title-* files of tests/data/bad/ (test_bad_scenes.cpp).
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "scene/color.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::only_layer;
using test::p6_with;
using test::p6_with_middle;

Scene p6(const std::string& extra) { return parse_scene(p6_with(extra), "s.json"); }

Color rgb(double r, double g, double b, double a = 1.0) { return Color{r, g, b, a}; }

void expect_same_line(const LineStyle& actual, const LineStyle& expected) {
  EXPECT_EQ(actual.color, expected.color);
  EXPECT_EQ(actual.width, expected.width);
  EXPECT_EQ(actual.opacity, expected.opacity);
  EXPECT_EQ(actual.dash, expected.dash);
}

void expect_same_keyframes(const std::vector<Keyframe>& actual,
                           const std::vector<Keyframe>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(actual[i].t, expected[i].t);
    EXPECT_EQ(actual[i].arrow.p, expected[i].arrow.p);
    EXPECT_EQ(actual[i].arrow.m, expected[i].arrow.m);
    EXPECT_EQ(actual[i].arrow.w, expected[i].arrow.w);
  }
}

// ------------------------------------------------------------ defaults

TEST(FigureDefaults, SceneWithoutFigureFields) {
  const Scene scene = p6("");
  EXPECT_EQ(scene.title, "");
  const Canvas canvas;
  EXPECT_EQ(scene.canvas.width, 800);
  EXPECT_EQ(scene.canvas.height, 600);
  EXPECT_EQ(scene.canvas.background, canvas.background);
  EXPECT_FALSE(scene.canvas.view.has_value());
  EXPECT_FALSE(scene.canvas.shared_fit);
  EXPECT_EQ(scene.canvas.margin, canvas.margin);
  EXPECT_TRUE(scene.canvas.y_up);
  EXPECT_EQ(scene.canvas.columns, 0);
  EXPECT_EQ(scene.canvas.font, "Sans");

  ASSERT_EQ(scene.layers.size(), 2U);
  ASSERT_TRUE(std::holds_alternative<PatternLayer>(scene.layers[0]));
  ASSERT_TRUE(std::holds_alternative<KeyframesLayer>(scene.layers[1]));
  expect_same_line(std::get<PatternLayer>(scene.layers[0]).line, PatternLayer{}.line);
  EXPECT_EQ(std::get<KeyframesLayer>(scene.layers[1]).colors, KeyframesLayer{}.colors);

  ASSERT_EQ(scene.panels.size(), 1U);
  const Panel& panel = scene.panels[0];
  EXPECT_EQ(panel.title, "");
  EXPECT_EQ(panel.pointer, "");
  EXPECT_EQ(track_keys(panel).method, Method::P6);
  EXPECT_EQ(method_id(panel.keys), "P6");
  EXPECT_EQ(panel.samples, kDefaultFigureSamples);
  EXPECT_FALSE(panel.layers.has_value());
  expect_same_keyframes(arrow_keys(panel).keyframes, arrow_keys(scene).keyframes);
}

TEST(FigureDefaults, ScenePanelTakesTheScenesSamplesAndOptions) {
  const Scene scene = p6(R"(, "samples": 31, "options": {"anchor": "midpoint"})");
  ASSERT_EQ(scene.panels.size(), 1U);
  EXPECT_EQ(scene.panels[0].samples, 31);
  EXPECT_EQ(track_keys(scene.panels[0]).options.anchor, Anchor::midpoint);
}

TEST(FigureDefaults, EmptyLayersDrawNothing) { EXPECT_TRUE(p6(R"(, "layers": [])").layers.empty()); }

TEST(FigureDefaults, WithMethodMovesTheScenePanel) {
  const Scene scene = with_method(p6(""), Method::P1);
  EXPECT_EQ(track_keys(scene.panels.at(0)).method, Method::P1);
  EXPECT_EQ(method_id(scene.panels.at(0).keys), "P1");
  // Panels of their own keep their method.
  const Scene own = with_method(p6(R"(, "panels": ["P2"])"), Method::P1);
  EXPECT_EQ(track_keys(own.panels.at(0)).method, Method::P2);
}

// ------------------------------------------------------------ title and canvas

TEST(Canvas, ReadsEveryField) {
  const Scene scene = p6(R"(, "title": "Fig. 1", "canvas": {"width": 1024, "height": 16,
      "background": "#102030", "view": {"min": [-1, -2], "max": [3, 4]}, "margin": 0.45,
      "y_axis": "down", "columns": 4, "font": "DejaVu Serif"})");
  EXPECT_EQ(scene.title, "Fig. 1");
  EXPECT_EQ(scene.canvas.width, 1024);
  EXPECT_EQ(scene.canvas.height, 16);
  EXPECT_EQ(scene.canvas.background, parse_color("#102030"));
  ASSERT_TRUE(scene.canvas.view.has_value());
  EXPECT_EQ(scene.canvas.view->min, make_point(-1, -2));
  EXPECT_EQ(scene.canvas.view->max, make_point(3, 4));
  EXPECT_FALSE(scene.canvas.shared_fit);
  EXPECT_EQ(scene.canvas.margin, 0.45);
  EXPECT_FALSE(scene.canvas.y_up);
  EXPECT_EQ(scene.canvas.columns, 4);
  EXPECT_EQ(scene.canvas.font, "DejaVu Serif");
}

TEST(Canvas, BackgroundNoneIsTransparent) {
  EXPECT_FALSE(p6(R"(, "canvas": {"background": "none"})").canvas.background.has_value());
  EXPECT_EQ(p6(R"(, "canvas": {"background": "white"})").canvas.background, rgb(1, 1, 1));
}

TEST(Canvas, ViewAutoAndShared) {
  const Scene shared = p6(R"(, "canvas": {"view": "shared"})");
  EXPECT_TRUE(shared.canvas.shared_fit);
  EXPECT_FALSE(shared.canvas.view.has_value());
  const Scene fit = p6(R"(, "canvas": {"view": "auto", "y_axis": "up"})");
  EXPECT_FALSE(fit.canvas.shared_fit);
  EXPECT_FALSE(fit.canvas.view.has_value());
  EXPECT_TRUE(fit.canvas.y_up);
}

// ------------------------------------------------------------ layers

TEST(Layers, Pattern) {
  const PatternLayer layer = only_layer<PatternLayer>(
      R"({"type": "pattern", "color": "#ff0000", "width": 2.5, "opacity": 0.5, "dash": [3, 1.5],
          "extended": true, "coils": true, "samples": 40, "range": [-0.5, 2]})");
  expect_same_line(layer.line, LineStyle{rgb(1, 0, 0), 2.5, 0.5, {3, 1.5}});
  EXPECT_TRUE(layer.extended);
  EXPECT_TRUE(layer.coils);
  EXPECT_EQ(layer.samples, 40);
  ASSERT_TRUE(layer.range.has_value());
  EXPECT_EQ(layer.range->from, -0.5);
  EXPECT_EQ(layer.range->to, 2);
}

TEST(Layers, PatternTimesMethodDots) {
  const PatternLayer layer = only_layer<PatternLayer>(
      R"({"type": "pattern", "times": [0.25, -1, 3], "method": "pa-po", "dots": true})");
  EXPECT_EQ(layer.times, (std::vector<double>{0.25, -1, 3}));
  ASSERT_TRUE(layer.method.has_value());
  EXPECT_EQ(*layer.method, Method::PaPo);
  EXPECT_TRUE(layer.dots);
  const PatternLayer plain = only_layer<PatternLayer>(R"({"type": "pattern"})");
  EXPECT_TRUE(plain.times.empty());
  EXPECT_FALSE(plain.method.has_value());
  EXPECT_FALSE(plain.dots);
}

TEST(Layers, LineFieldsOverrideOnlyWhatIsGiven) {
  const PatternLayer pattern = only_layer<PatternLayer>(R"({"type": "pattern", "width": 3})");
  LineStyle expected = PatternLayer{}.line;
  expected.width = 3;
  expect_same_line(pattern.line, expected);
  EXPECT_FALSE(pattern.samples.has_value());
  EXPECT_FALSE(pattern.range.has_value());
  EXPECT_FALSE(pattern.extended);
  EXPECT_FALSE(pattern.coils);

  const TrajectoryLayer trajectory =
      only_layer<TrajectoryLayer>(R"({"type": "trajectory", "color": "blue"})");
  expected = TrajectoryLayer{}.line;
  expected.color = parse_color("blue");
  expect_same_line(trajectory.line, expected);

  const DiscrepancyLayer discrepancy =
      only_layer<DiscrepancyLayer>(R"({"type": "discrepancy", "dash": []})");
  expect_same_line(discrepancy.line, DiscrepancyLayer{}.line);
}

TEST(Layers, Keyframes) {
  const KeyframesLayer layer = only_layer<KeyframesLayer>(
      R"({"type": "keyframes", "colors": ["black", "#0f0"], "width": 1, "opacity": 0.25,
          "winding": false, "spiral_center": "midpoint", "extended": true})");
  EXPECT_EQ(layer.colors, (std::vector<Color>{rgb(0, 0, 0), rgb(0, 1, 0)}));
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
  EXPECT_EQ(only_layer<TrajectoryLayer>(R"({"type": "trajectory", "point": "q"})").point,
            TrackedPoint::end);
  const TrajectoryLayer plain = only_layer<TrajectoryLayer>(R"({"type": "trajectory"})");
  EXPECT_EQ(plain.point, TrackedPoint::start);
  EXPECT_EQ(plain.samples, 512);
}

TEST(Layers, Stroke) {
  const StrokeLayer layer = only_layer<StrokeLayer>(
      R"({"type": "stroke", "fill": "#00000080", "opacity": 0.5,
          "outline": {"color": "red", "dash": [2, 2]}, "samples": 2, "range": [0.25, 0.75]})");
  EXPECT_EQ(layer.fill, rgb(0, 0, 0, 128 / 255.0));
  EXPECT_EQ(layer.opacity, 0.5);
  ASSERT_TRUE(layer.outline.has_value());
  expect_same_line(*layer.outline, LineStyle{parse_color("red"), 1.0, 1.0, {2, 2}});
  EXPECT_EQ(layer.samples, 2);
  EXPECT_EQ(layer.range->from, 0.25);
  EXPECT_FALSE(only_layer<StrokeLayer>(R"({"type": "stroke"})").outline.has_value());
  expect_same_line(*only_layer<StrokeLayer>(R"({"type": "stroke", "outline": {}})").outline,
                   LineStyle{});
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
  EXPECT_EQ(only_layer<BannerLayer>(R"({"type": "banner", "text": ")" + long_text + "\"}").text,
            long_text);
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
  const DiscrepancyLayer plain =
      only_layer<DiscrepancyLayer>(R"({"type": "discrepancy", "predictor": "pita"})");
  EXPECT_FALSE(plain.method.has_value());  // the panel's method
  EXPECT_FALSE(plain.fill.has_value());
  EXPECT_EQ(plain.scale, 30);
  EXPECT_EQ(only_layer<DiscrepancyLayer>(R"({"type": "discrepancy", "predictor": "average"})")
                .predictor,
            Predictor::average);
  EXPECT_EQ(only_layer<DiscrepancyLayer>(R"({"type": "discrepancy"})").predictor,
            Predictor::previous);
}

TEST(Layers, LabelAndLegend) {
  const LabelLayer label = only_layer<LabelLayer>(
      R"({"type": "label", "text": "A", "at": [1.5, -2], "size": 200, "color": "#808080"})");
  EXPECT_EQ(label.text, "A");
  EXPECT_EQ(label.at, make_point(1.5, -2));
  EXPECT_EQ(label.size, 200);
  EXPECT_EQ(label.color, parse_color("gray"));
  EXPECT_EQ(only_layer<LabelLayer>(R"({"type": "label", "text": "B", "at": [0, 0]})").size, 12);

  const LegendLayer legend =
      only_layer<LegendLayer>(R"({"type": "legend", "corner": "bottom-left", "size": 9})");
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

std::vector<std::string> texts(const std::vector<MeasureName>& show) {
  std::vector<std::string> out;
  for (const MeasureName& name : show) out.push_back(name.text);
  return out;
}

TEST(Layers, Measures) {
  const MeasuresLayer defaults = only_layer<MeasuresLayer>(R"({"type": "measures"})");
  EXPECT_EQ(texts(defaults.show), (std::vector<std::string>{"overreaction", "pop"}));
  EXPECT_FALSE(defaults.at.has_value());
  EXPECT_EQ(defaults.corner, LegendLayer::Corner::bottom_left);
  const MeasuresLayer placed = only_layer<MeasuresLayer>(
      R"({"type": "measures", "show": ["pop", "gain:B.q", "jump:K27.p.x"], "at": [1, 2], "size": 9, "color": "#0000ff"})");
  EXPECT_EQ(texts(placed.show), (std::vector<std::string>{"pop", "gain:B.q", "jump:K27.p.x"}));
  EXPECT_EQ(placed.show[1].kind, MeasureKind::gain);
  EXPECT_EQ(placed.show[1].parameter, "B.q");
  ASSERT_TRUE(placed.at.has_value());
  EXPECT_EQ(*placed.at, (Point{1.0, 2.0}));
  EXPECT_EQ(placed.size, 9.0);
  EXPECT_EQ(placed.color, rgb(0, 0, 1));
  EXPECT_EQ(only_layer<MeasuresLayer>(R"({"type": "measures", "at": "top-right"})").corner,
            LegendLayer::Corner::top_right);
  // Each name is parsed by scene/measure_name.cpp (tests/scene/test_measure_name.cpp);
  // a refused one is the reader's error at its pointer.
  try {
    p6(R"(, "layers": [{"type": "measures", "show": ["pop", "ara"]}])");
    ADD_FAILURE() << "an arrow scene showing \"ara\" was accepted";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/layers/0/show/1");
    EXPECT_NE(std::string(error.what()).find("pose scenes only"), std::string::npos) << error.what();
  }
}

TEST(Layers, KeepTheirOrder) {
  const Scene scene = p6(R"(, "layers": [{"type": "legend"}, {"type": "stroke"},
      {"type": "pattern"}, {"type": "legend"}])");
  ASSERT_EQ(scene.layers.size(), 4U);
  EXPECT_EQ(scene.layers[0].index(), 7U);
  EXPECT_EQ(scene.layers[1].index(), 3U);
  EXPECT_EQ(scene.layers[2].index(), 0U);
  EXPECT_EQ(scene.layers[3].index(), 7U);
}

// ------------------------------------------------------------ panels

TEST(Panels, MethodNames) {
  const Scene scene = p6(R"(, "samples": 5, "panels": ["P1", "la-lp", "P6:La-LP", "5s"])");
  ASSERT_EQ(scene.panels.size(), 4U);
  EXPECT_EQ(track_keys(scene.panels[0]).method, Method::P1);
  EXPECT_EQ(method_id(scene.panels[0].keys), "P1");
  EXPECT_EQ(scene.panels[0].title, "P1 Pa-Ca");
  EXPECT_EQ(scene.panels[0].pointer, "/panels/0");
  EXPECT_EQ(scene.panels[1].title, "P6 La-LP");
  EXPECT_EQ(scene.panels[2].title, "P6 La-LP");
  EXPECT_EQ(track_keys(scene.panels[3]).method, Method::P5S);
  EXPECT_EQ(scene.panels[3].title, "P5S Hs-LP");
  EXPECT_EQ(scene.panels[3].pointer, "/panels/3");
  for (const Panel& panel : scene.panels) {
    expect_same_keyframes(arrow_keys(panel).keyframes, arrow_keys(scene).keyframes);
    EXPECT_EQ(panel.samples, 5);
    EXPECT_FALSE(panel.layers.has_value());
  }
}

TEST(Panels, SmaIsTitledByItsId) {
  const Scene scene = parse_scene(R"({"method": "SMA", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 0], "m": 2, "w": 1}],
      "panels": ["sma"]})",
                                  "s.json");
  EXPECT_EQ(scene.panels.at(0).title, "SMA");
  EXPECT_EQ(track_keys(scene.panels.at(0)).method, Method::SMA);
}

TEST(Panels, ObjectsOverrideTheScene) {
  const Scene scene = p6(R"(, "samples": 21, "options": {"path_mean": "harmonic"}, "panels": [
      {},
      {"title": "mine"},
      {"method": "P2", "options": {"anchor": "midpoint"}},
      {"method": "P9", "title": ""},
      {"keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 2, "p": [1, 0], "m": 1, "w": 1},
                     {"t": 3, "p": [2, 0], "m": 1, "w": 2}], "samples": 3},
      {"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
                                      {"t": 1, "p": [1, 0], "m": 2, "w": 1}]},
      {"layers": [{"type": "trajectory"}]}
    ])");
  ASSERT_EQ(scene.panels.size(), 7U);
  const Panel& plain = scene.panels[0];
  EXPECT_EQ(plain.title, "");  // no method named: no title
  EXPECT_EQ(track_keys(plain).method, Method::P6);
  EXPECT_EQ(plain.samples, 21);
  EXPECT_EQ(track_keys(plain).options.path_mean, MeanKind::harmonic);
  EXPECT_EQ(plain.pointer, "/panels/0");

  EXPECT_EQ(scene.panels[1].title, "mine");
  EXPECT_EQ(track_keys(scene.panels[1]).method, Method::P6);

  const Panel& p2 = scene.panels[2];
  EXPECT_EQ(track_keys(p2).method, Method::P2);
  EXPECT_EQ(p2.title, "P2 LS-Po");
  EXPECT_EQ(track_keys(p2).options.anchor, Anchor::midpoint);
  EXPECT_EQ(track_keys(p2).options.path_mean, MeanKind::harmonic);  // the scene's, not given by the panel
  EXPECT_EQ(track_keys(p2).options.magnitude_mean, MeanKind::geometric);

  EXPECT_EQ(track_keys(scene.panels[3]).method, Method::P9);
  EXPECT_EQ(scene.panels[3].title, "");  // an explicit "" wins

  const Panel& own = scene.panels[4];
  ASSERT_EQ(arrow_keys(own).keyframes.size(), 3U);
  EXPECT_EQ(arrow_keys(own).keyframes[1].t, 2);
  EXPECT_EQ(arrow_keys(own).keyframes[2].arrow.w, 2);
  EXPECT_EQ(own.samples, 3);
  EXPECT_EQ(track_keys(own).method, Method::P6);

  const Panel& sma = scene.panels[5];
  EXPECT_EQ(track_keys(sma).method, Method::SMA);
  EXPECT_EQ(method_id(sma.keys), "SMA");
  EXPECT_EQ(sma.title, "SMA");
  EXPECT_EQ(arrow_keys(sma).keyframes.size(), 2U);

  ASSERT_TRUE(scene.panels[6].layers.has_value());
  ASSERT_EQ(scene.panels[6].layers->size(), 1U);
  EXPECT_TRUE(std::holds_alternative<TrajectoryLayer>(scene.panels[6].layers->at(0)));
  EXPECT_EQ(scene.panels[6].pointer, "/panels/6");
  EXPECT_EQ(scene.layers.size(), 2U);  // the scene's own layers are still the defaults
}

TEST(Panels, SamplesDefaultWithoutTheScenesSamples) {
  const Scene scene = p6(R"(, "panels": ["P1", {"samples": 4}])");
  EXPECT_EQ(scene.panels.at(0).samples, kDefaultFigureSamples);
  EXPECT_EQ(scene.panels.at(1).samples, 4);
}

// "swept" (SAM Fig. 10): the edge, the parts hidden by false or restyled
// over their defaults, and the claim's place.
TEST(FigureReader, SweptLayer) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
      {"t": 1, "matrix": [[0, -1, 2], [1, 0, 0]]}], "layers": [{"type": "swept", "edge": [[0, 1], [2, 1]],
      "instants": 5, "trace_samples": 64, "ends": false, "grazing": {"width": 3}, "claim_at": [0, -1]}]})",
                                  "s.json");
  ASSERT_EQ(scene.pose_layers.size(), 1u);
  const auto& layer = std::get<SweptLayer>(scene.pose_layers[0]);
  EXPECT_EQ(layer.edge[0], Point(0.0, 1.0));
  EXPECT_EQ(layer.edge[1], Point(2.0, 1.0));
  EXPECT_EQ(layer.instants, 5);
  EXPECT_EQ(layer.trace_samples, 64);
  EXPECT_FALSE(layer.ends.has_value());
  ASSERT_TRUE(layer.grazing.has_value());
  EXPECT_EQ(layer.grazing->width, 3.0);
  EXPECT_EQ(layer.grazing->color, SweptLayer{}.grazing->color);  // unset members keep the default
  ASSERT_TRUE(layer.segments.has_value());
  ASSERT_TRUE(layer.envelope.has_value());
  EXPECT_EQ(layer.claim_at, std::optional<Point>(Point(0.0, -1.0)));
  EXPECT_FALSE(SweptLayer{}.claim_at.has_value());
}

}  // namespace
}  // namespace pita::scene
