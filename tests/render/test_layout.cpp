// Where panels go and how the plane maps onto them (src/render/layout.cpp):
// the grid below the title, the view of each panel (given, its own drawing's
// box, or one shared box) and the similarity that fits it into the plot area.
#include <vector>

#include <gtest/gtest.h>

#include "render/figure.hpp"
#include "render/layout.hpp"
#include "render_support.hpp"

namespace pita::render::test {
namespace {

// A drawing of one open polyline through `points`.
Drawing polyline(std::vector<Point> points) {
  Drawing d;
  d.items.push_back({"/layers/0", -1, Polyline{std::move(points), false, {}}});
  return d;
}

// `n` untitled panels on a canvas without title or margins.
scene::Scene bare(int n, int width, int height) {
  std::vector<scene::Panel> panels;
  for (int i = 0; i < n; ++i) {
    panels.push_back(panel(Method::P6, three_keyframes()));
    panels.back().title.clear();
  }
  scene::Scene s = scene_with({}, panels);
  s.canvas.width = width;
  s.canvas.height = height;
  s.canvas.margin = 0.0;
  return s;
}

TEST(Layout, GridOfPanelsBelowTheTitle) {
  const scene::Scene s = eight_panels();
  const Figure f = build_figure(s);
  ASSERT_EQ(f.placements.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    const Rect& cell = f.placements[i].cell;
    EXPECT_DOUBLE_EQ(cell.width, 300.0);
    const double column = static_cast<double>(i % 4), row = static_cast<double>(i / 4);
    EXPECT_DOUBLE_EQ(cell.x, 300.0 * column);
    EXPECT_DOUBLE_EQ(cell.y, kTitleBand + (900.0 - kTitleBand) / 2 * row);
  }
}

// A corner legend gets room of its own above or below the drawing (at most a
// third of the panel); with a shared view every panel leaves the most room,
// so that one scale holds.
TEST(Layout, CornerLegendsGetRoomOfTheirOwn) {
  const scene::Scene s = bare(2, 400, 300);  // two cells of 200 x 300
  Drawing bottom = polyline({{0.0, 0.0}, {1.0, 1.0}});
  bottom.legends.push_back(Legend{scene::LegendLayer::Corner::bottom_left, 10.0, {{}, {}, {}}, true, "/layers/1"});
  Drawing top = polyline({{0.0, 0.0}, {1.0, 1.0}});
  top.legends.push_back(Legend{scene::LegendLayer::Corner::top_right, 10.0, {{}, {}}, true, "/layers/1"});
  const std::vector<PanelPlacement> p = layout_panels(s, {bottom, top});
  const double three_lines = 3 * kLegendLineHeight * 10.0 + 2 * kLegendPad;
  EXPECT_DOUBLE_EQ(p[0].plot.y, 0.0);
  EXPECT_DOUBLE_EQ(p[0].plot.height, 300.0 - three_lines);
  const double two_lines = 2 * kLegendLineHeight * 10.0 + 2 * kLegendPad;
  EXPECT_DOUBLE_EQ(p[1].plot.y, two_lines);
  EXPECT_DOUBLE_EQ(p[1].plot.height, 300.0 - two_lines);
  // The room is at most a third of the panel.
  Drawing tall = polyline({{0.0, 0.0}, {1.0, 1.0}});
  tall.legends.push_back(Legend{scene::LegendLayer::Corner::top_left, 10.0, std::vector<LegendEntry>(40), true, ""});
  EXPECT_DOUBLE_EQ(layout_panels(bare(1, 200, 300), {tall})[0].plot.y, 100.0);
  // Shared: both panels leave the room of both legends, and keep one scale.
  scene::Scene shared = s;
  shared.canvas.shared_fit = true;
  const std::vector<PanelPlacement> q = layout_panels(shared, {bottom, top});
  EXPECT_DOUBLE_EQ(q[0].plot.y, two_lines);
  EXPECT_DOUBLE_EQ(q[1].plot.height, 300.0 - two_lines - three_lines);
  EXPECT_DOUBLE_EQ(q[0].transform.scale, q[1].transform.scale);
}

TEST(Layout, ViewFitsTheDrawingInsideThePlot) {
  const scene::Scene s = eight_panels();
  const Figure f = build_figure(s);
  for (std::size_t i = 0; i < 8; ++i) {
    const PanelPlacement& p = f.placements[i];
    const auto box = bounds(f.drawings[i]);
    ASSERT_TRUE(box);
    for (Point corner : {box->min, box->max, Point{box->min.real(), box->max.imag()}}) {
      const Point c = p.transform(corner);
      EXPECT_GE(c.real(), p.plot.x - 1e-9);
      EXPECT_LE(c.real(), p.plot.x + p.plot.width + 1e-9);
      EXPECT_GE(c.imag(), p.plot.y - 1e-9);
      EXPECT_LE(c.imag(), p.plot.y + p.plot.height + 1e-9);
    }
    // y up: a point above maps higher on the canvas (smaller y).
    EXPECT_LT(p.transform({0.0, 1.0}).imag(), p.transform({0.0, 0.0}).imag());
  }
}

// A 4 x 2 view in a 400 x 300 plot: 100 pixels per unit (the width decides),
// centred, y up: (0, 0) goes to (0, 250) and (4, 2) to (400, 50).
TEST(Layout, GivenViewIsFittedKeepingProportions) {
  scene::Scene s = bare(1, 400, 300);
  s.canvas.view = scene::Box{{0.0, 0.0}, {4.0, 2.0}};
  const std::vector<PanelPlacement> p = layout_panels(s, {polyline({{10.0, 10.0}, {11.0, 12.0}})});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_DOUBLE_EQ(p[0].plot.width, 400.0);
  EXPECT_DOUBLE_EQ(p[0].plot.height, 300.0);
  EXPECT_DOUBLE_EQ(p[0].transform.scale, 100.0);
  const Point low = p[0].transform({0.0, 0.0}), high = p[0].transform({4.0, 2.0});
  EXPECT_DOUBLE_EQ(low.real(), 0.0);
  EXPECT_DOUBLE_EQ(low.imag(), 250.0);
  EXPECT_DOUBLE_EQ(high.real(), 400.0);
  EXPECT_DOUBLE_EQ(high.imag(), 50.0);
  // y down: the same point goes below the centre.
  s.canvas.y_up = false;
  EXPECT_DOUBLE_EQ(layout_panels(s, {polyline({{0.0, 0.0}, {1.0, 1.0}})})[0].transform({4.0, 2.0}).imag(), 250.0);
}

// Five panels: ceil(sqrt(5)) = 3 columns, 2 rows; a titled panel gives its
// title band to the title and the rest to the plot; a 10 % margin of the
// smaller side is taken on every side.
TEST(Layout, FivePanelsMakeThreeColumnsWithTitleBandsAndMargins) {
  scene::Scene s = bare(5, 600, 400);
  s.panels[4].title = "P6";
  s.canvas.margin = 0.1;
  std::vector<Drawing> drawings(5, polyline({{0.0, 0.0}, {1.0, 1.0}}));
  const std::vector<PanelPlacement> p = layout_panels(s, drawings);
  ASSERT_EQ(p.size(), 5u);
  EXPECT_DOUBLE_EQ(p[4].cell.x, 200.0);
  EXPECT_DOUBLE_EQ(p[4].cell.y, 200.0);
  EXPECT_DOUBLE_EQ(p[4].cell.width, 200.0);
  EXPECT_DOUBLE_EQ(p[4].cell.height, 200.0);
  EXPECT_DOUBLE_EQ(p[4].title.height, kPanelTitleBand);
  EXPECT_DOUBLE_EQ(p[0].title.height, 0.0);
  // Panel 0: margin 0.1 * 200 = 20. Panel 4: the inner area is 200 x (200 - 22).
  EXPECT_DOUBLE_EQ(p[0].plot.x, 20.0);
  EXPECT_DOUBLE_EQ(p[0].plot.width, 160.0);
  const double margin = 0.1 * (200.0 - kPanelTitleBand);
  EXPECT_DOUBLE_EQ(p[4].plot.y, 200.0 + kPanelTitleBand + margin);
  EXPECT_DOUBLE_EQ(p[4].plot.width, 200.0 - 2.0 * margin);
}

TEST(Layout, SharedViewIsTheBoxOfEveryDrawing) {
  scene::Scene s = bare(2, 400, 200);
  s.canvas.shared_fit = true;
  const std::vector<PanelPlacement> p =
      layout_panels(s, {polyline({{0.0, 0.0}, {1.0, 2.0}}), polyline({{-3.0, 1.0}, {0.5, 4.0}})});
  for (const PanelPlacement& placement : p) {
    EXPECT_EQ(placement.view.min, (Point{-3.0, 0.0}));
    EXPECT_EQ(placement.view.max, (Point{1.0, 4.0}));
  }
  // Each its own box otherwise.
  s.canvas.shared_fit = false;
  const std::vector<PanelPlacement> own =
      layout_panels(s, {polyline({{0.0, 0.0}, {1.0, 2.0}}), polyline({{-3.0, 1.0}, {0.5, 4.0}})});
  EXPECT_EQ(own[0].view.max, (Point{1.0, 2.0}));
  EXPECT_EQ(own[1].view.min, (Point{-3.0, 1.0}));
}

// A vertical segment of length 2 gets a width of 1e-3 of it; an empty drawing
// shows [-1, 1]^2.
TEST(Layout, FlatOrEmptyDrawingsStillGetAnArea) {
  const scene::Scene s = bare(2, 400, 200);
  const std::vector<PanelPlacement> p = layout_panels(s, {polyline({{5.0, 0.0}, {5.0, 2.0}}), Drawing{}});
  EXPECT_NEAR(p[0].view.min.real(), 5.0 - 1e-3, 1e-15);
  EXPECT_NEAR(p[0].view.max.real(), 5.0 + 1e-3, 1e-15);
  EXPECT_EQ(p[0].view.min.imag(), 0.0);
  EXPECT_EQ(p[1].view.min, (Point{-1.0, -1.0}));
  EXPECT_EQ(p[1].view.max, (Point{1.0, 1.0}));
  EXPECT_TRUE(layout_panels(s, {}).empty());
}

}  // namespace
}  // namespace pita::render::test
