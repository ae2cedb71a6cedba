// The figure part of a scene (src/scene/figure_reader.cpp and the panels of
// src/scene/scene.cpp): title, canvas, layers and panels, and their defaults.
// The pointer and reason of every kind of error: the canvas-*, layers-*,
// panels-* and title-* files of tests/data/bad/ (test_bad_scenes.cpp).
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "scene/color.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::expect_same_line;
using test::only_layer;
using test::p6_with;
using test::p6_with_middle;

Scene p6(const std::string& extra) { return parse_scene(p6_with(extra), "s.json"); }

Color rgb(double r, double g, double b, double a = 1.0) { return Color{r, g, b, a}; }

void expect_same_keyframes(const std::vector<Keyframe>& actual, const std::vector<Keyframe>& expected) {
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

  ASSERT_EQ(figure_of<KeyframeKeys>(scene).layers.size(), 2U);
  ASSERT_TRUE(std::holds_alternative<PatternLayer>(figure_of<KeyframeKeys>(scene).layers[0]));
  ASSERT_TRUE(std::holds_alternative<KeyframesLayer>(figure_of<KeyframeKeys>(scene).layers[1]));
  expect_same_line(std::get<PatternLayer>(figure_of<KeyframeKeys>(scene).layers[0]).line, PatternLayer{}.line);
  EXPECT_EQ(std::get<KeyframesLayer>(figure_of<KeyframeKeys>(scene).layers[1]).colors, KeyframesLayer{}.colors);

  ASSERT_EQ(scene.panels.size(), 1U);
  const Panel& panel = scene.panels[0];
  EXPECT_EQ(panel.title, "");
  EXPECT_EQ(panel.pointer, "");
  EXPECT_EQ(track_keys(panel).method, Method::P6);
  EXPECT_EQ(method_id(panel.keys), "P6");
  EXPECT_EQ(panel.samples, kDefaultFigureSamples);
  EXPECT_FALSE(figure_of<KeyframeKeys>(panel).layers.has_value());
  expect_same_keyframes(arrow_keys(panel).keyframes, arrow_keys(scene).keyframes);
}

TEST(FigureDefaults, ScenePanelTakesTheScenesSamplesAndOptions) {
  const Scene scene = p6(R"(, "samples": 31, "options": {"knots": "as-given"})");
  ASSERT_EQ(scene.panels.size(), 1U);
  EXPECT_EQ(scene.panels[0].samples, 31);
  EXPECT_EQ(track_keys(scene.panels[0]).options.knots, KnotOrder::as_given);
}

TEST(FigureDefaults, EmptyLayersDrawNothing) {
  EXPECT_TRUE(figure_of<KeyframeKeys>(p6(R"(, "layers": [])")).layers.empty());
}

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

// ------------------------------------------------------------ layers (each kind: test_arrow_layer_reader.cpp,
// test_pose_layer_reader.cpp)

TEST(Layers, KeepTheirOrder) {
  const Scene scene = p6(R"(, "layers": [{"type": "legend"}, {"type": "stroke"},
      {"type": "pattern"}, {"type": "legend"}])");
  ASSERT_EQ(figure_of<KeyframeKeys>(scene).layers.size(), 4U);
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).layers[0].index(), 7U);
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).layers[1].index(), 3U);
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).layers[2].index(), 0U);
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).layers[3].index(), 7U);
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
    EXPECT_FALSE(figure_of<KeyframeKeys>(panel).layers.has_value());
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

  ASSERT_TRUE(figure_of<KeyframeKeys>(scene.panels[6]).layers.has_value());
  ASSERT_EQ(figure_of<KeyframeKeys>(scene.panels[6]).layers->size(), 1U);
  EXPECT_TRUE(std::holds_alternative<TrajectoryLayer>(figure_of<KeyframeKeys>(scene.panels[6]).layers->at(0)));
  EXPECT_EQ(scene.panels[6].pointer, "/panels/6");
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).layers.size(), 2U);  // the scene's own layers are still the defaults
}

TEST(Panels, SamplesDefaultWithoutTheScenesSamples) {
  const Scene scene = p6(R"(, "panels": ["P1", {"samples": 4}])");
  EXPECT_EQ(scene.panels.at(0).samples, kDefaultFigureSamples);
  EXPECT_EQ(scene.panels.at(1).samples, 4);
}

}  // namespace
}  // namespace pita::scene
