// The figure as the lint sees it (src/lint/geometry.cpp): each text, stroke
// and legend lands on the canvas where the painter puts it, tagged with its
// layer (the geometry of edges and boxes: tests/render/test_canvas_geometry.cpp).
#include <gtest/gtest.h>

#include "lint/geometry.hpp"
#include "lint_support.hpp"

namespace pita::lint {
namespace {

// A label at a world point: its ink box starts at the point's canvas x and
// is centred near its y; the pattern's frames are "pattern" data of
// /layers/0, one segment each, inside the panel.
TEST(LintGeometry, LabelsAndFramesLandWhereThePainterPutsThem) {
  const scene::Scene scene = scene::parse_scene(
      test::arrow_scene(
          R"("layers": [{"type": "pattern"}, {"type": "label", "text": "Hello", "at": [3, -1], "size": 20}])"),
      "test.json");
  const render::Figure figure = render::build_figure(scene);
  const FigureGeometry geometry = figure_geometry(scene, figure);
  ASSERT_EQ(geometry.panels.size(), 1u);
  const PanelGeometry& panel = geometry.panels[0];
  ASSERT_EQ(panel.texts.size(), 1u);
  const TextBox& label = panel.texts[0];
  EXPECT_EQ(label.owner, "/layers/1");
  EXPECT_EQ(label.text, "Hello");
  const Point at = figure.placements[0].transform({3, -1});
  EXPECT_NEAR(label.box.x, at.real(), 3.0);  // ink starts at the anchor (less the H's side bearing)
  EXPECT_GT(label.box.width, 30.0);          // five letters at 20 px
  EXPECT_NEAR(label.box.y + 0.5 * label.box.height, at.imag(), 6.0);
  EXPECT_EQ(panel.data.size(), 9u);  // the nine frames
  for (const DataShape& frame : panel.data) {
    EXPECT_EQ(frame.layer, "/layers/0");
    EXPECT_EQ(frame.type, "pattern");
    EXPECT_TRUE(frame.frame);
    EXPECT_EQ(frame.edges.size(), 1u);
    EXPECT_GE(frame.bounds.x, panel.area.x);
    EXPECT_LE(frame.bounds.x + frame.bounds.width, panel.area.x + panel.area.width);
  }
}

// A legend's box is in its corner of the panel, and its lines are texts of its layer.
TEST(LintGeometry, LegendsInTheirCorner) {
  const scene::Scene scene = scene::parse_scene(
      test::arrow_scene(R"("layers": [{"type": "pattern"}, {"type": "legend", "corner": "bottom-right"}])"),
      "test.json");
  const FigureGeometry geometry = figure_geometry(scene, render::build_figure(scene));
  const PanelGeometry& panel = geometry.panels[0];
  ASSERT_EQ(panel.legends.size(), 1u);
  EXPECT_EQ(panel.legends[0].layer, "/layers/1");
  EXPECT_GT(panel.legends[0].box.x, panel.area.x + 0.5 * panel.area.width);
  EXPECT_GT(panel.legends[0].box.y, panel.area.y + 0.5 * panel.area.height);
  ASSERT_FALSE(panel.texts.empty());
  EXPECT_EQ(panel.texts[0].kind, TextKind::legend);
  EXPECT_EQ(panel.texts[0].owner, "/layers/1");
}

}  // namespace
}  // namespace pita::lint
