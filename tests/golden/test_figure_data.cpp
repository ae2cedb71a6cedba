// The numbers a figure draws, as JSON (src/golden/figure_data.cpp): one item
// per shape with its layer and frame, the panel's extent, and the text form
// that reads back exactly.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "golden/figure_data.hpp"
#include "golden_support.hpp"

namespace pita::golden {
namespace {

TEST(FigureData, RecordsEveryShapeWithItsLayerAndFrame) {
  const Json data = data_of(kScene);
  ASSERT_EQ(data.at("panels").size(), 2u);
  const Json& items = data.at("panels")[1].at("items");
  // 17 frames (the default for figures), 16 circles (from the second frame),
  // 3 keyframes x (spiral + arrow).
  EXPECT_EQ(items.size(), 17u + 16u + 6u);
  EXPECT_EQ(items[0].at("layer"), "/layers/0");
  EXPECT_EQ(items[0].at("index"), 0);
  EXPECT_TRUE(items[0].contains("polyline"));
  EXPECT_TRUE(items[17].contains("circle"));
  EXPECT_EQ(items[17].at("index"), 1);
  // The text form reads back to the same numbers, exactly.
  EXPECT_EQ(Json::parse(figure_data_text(data)), data);
}

// A figure built by hand: one panel with one shape of each kind.
struct HandMade {
  scene::Scene scene;
  render::Figure figure;
};

HandMade hand_made() {
  HandMade h;
  scene::Panel panel;
  panel.pointer = "/panels/0";
  panel.title = "P6 \"La-LP\"";
  h.scene.panels.push_back(panel);
  render::Drawing d;
  d.items.push_back({"/layers/0", 0, render::Polyline{{{0.0, 0.0}, {3.0, 4.0}}, false, {}}});
  d.items.push_back({"/layers/1", -1, render::FilledPath{{{{0.5, 0.5}, {1.0, 0.5}, {1.0, 1.0}}}, {}, 1.0, {}}});
  d.items.push_back({"/layers/2", 2, render::Circle{{1.0, 2.0}, 0.1, {}, {}}});
  d.items.push_back({"/layers/3", 1, render::ArrowShape{{0.0, 1.0}, {2.0, 1.0}, {}}});
  d.items.push_back({"/layers/4", -1, render::Label{"A", {3.0, 0.0}, 12.0, {}}});
  h.figure.drawings.push_back(d);
  return h;
}

TEST(FigureData, HandMadeFigureGivesEachShapeAsNumbers) {
  const HandMade h = hand_made();
  const Json data = figure_data("fig", h.scene, h.figure);
  const Json expected = Json::parse(R"({"scene": "fig", "panels": [
    {"pointer": "/panels/0", "title": "P6 \"La-LP\"", "extent": 5.0, "items": [
      {"layer": "/layers/0", "index": 0, "polyline": [[0.0, 0.0], [3.0, 4.0]]},
      {"layer": "/layers/1", "index": -1, "filled": [[[0.5, 0.5], [1.0, 0.5], [1.0, 1.0]]]},
      {"layer": "/layers/2", "index": 2, "circle": {"center": [1.0, 2.0], "radius": 0.1}},
      {"layer": "/layers/3", "index": 1, "arrow": [[0.0, 1.0], [2.0, 1.0]]},
      {"layer": "/layers/4", "index": -1, "label": {"text": "A", "at": [3.0, 0.0]}}]}]})");
  EXPECT_EQ(data, expected) << data.dump(1);
}

// The extent is the diagonal of the box of the drawing: here (0, 0)-(3, 4), 5;
// an empty drawing has extent 0.
TEST(FigureData, ExtentIsTheDiagonalOfTheDrawing) {
  HandMade h = hand_made();
  h.figure.drawings[0].items.push_back({"/layers/5", -1, render::Polyline{{{-3.0, 0.0}, {0.0, -4.0}}, false, {}}});
  h.scene.panels.push_back(h.scene.panels[0]);
  h.figure.drawings.push_back(render::Drawing{});
  const Json data = figure_data("fig", h.scene, h.figure);
  EXPECT_DOUBLE_EQ(data.at("panels")[0].at("extent").get<double>(), 10.0);  // (-3, -4)-(3, 4)
  EXPECT_EQ(data.at("panels")[1].at("extent").get<double>(), 0.0);
  EXPECT_TRUE(data.at("panels")[1].at("items").empty());
}

// One line per item between a line for the scene and one for each panel.
TEST(FigureData, TextHasOneItemPerLineAndReadsBackExactly) {
  HandMade h = hand_made();
  h.figure.drawings[0].items.push_back(
      {"/layers/5", -1, render::Polyline{{{0.1, 1.0 / 3.0}, {1e-300, -2.0 / 7.0}}, false, {}}});
  const Json data = figure_data("fig", h.scene, h.figure);
  const std::string text = figure_data_text(data);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 1 + 6 + 1 + 1);
  EXPECT_EQ(text.rfind("{\"scene\": \"fig\", \"panels\": [\n{\"pointer\": \"/panels/0\", \"title\": ", 0), 0u) << text;
  EXPECT_NE(text.find("\n  {\"layer\":\"/layers/0\",\"index\":0,\"polyline\":[[0.0,0.0],[3.0,4.0]]},\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("0.1,"), std::string::npos) << text;
  EXPECT_EQ(text.substr(text.size() - 6), "]}\n]}\n");
  const Json back = Json::parse(text);
  EXPECT_EQ(back, data);
  const Json& last = back.at("panels")[0].at("items")[5].at("polyline");
  EXPECT_EQ(last[0][1].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(last[1][0].get<double>(), 1e-300);
  EXPECT_EQ(last[1][1].get<double>(), -2.0 / 7.0);
}

}  // namespace
}  // namespace pita::golden
