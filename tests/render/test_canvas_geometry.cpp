// Shapes on the canvas (render/canvas_geometry.hpp): edges and boxes meet as
// geometry says, areas hold points by winding, and each shape's outline is
// its canvas image under the panel's view.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "render/canvas_geometry.hpp"

namespace pita::render {
namespace {

TEST(CanvasGeometry, SegmentMeetsBox) {
  const Rect box{10, 10, 20, 10};                                // x 10..30, y 10..20
  EXPECT_TRUE(edge_meets({{0, 15}, {40, 15}}, box));             // through it
  EXPECT_TRUE(edge_meets({{12, 12}, {14, 14}}, box));            // inside it
  EXPECT_TRUE(edge_meets({{0, 0}, {20, 15}}, box));              // ends inside
  EXPECT_FALSE(edge_meets({{0, 0}, {40, 5}}, box));              // above it
  EXPECT_FALSE(edge_meets({{0, 25}, {40, 25}}, box));            // below, parallel
  EXPECT_FALSE(edge_meets({{0, 29}, {14, 0}}, box));             // passes the corner (10, 10) on its outer side
  EXPECT_FALSE(edge_meets({{0, 40}, {40, 0}}, {30, 30, 5, 5}));  // the diagonal x + y = 40 misses x, y >= 30
}

TEST(CanvasGeometry, InsideByWinding) {
  const std::vector<Point> square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_TRUE(inside(square, {5, 5}));
  EXPECT_FALSE(inside(square, {15, 5}));
  std::vector<Point> reversed(square.rbegin(), square.rend());
  EXPECT_TRUE(inside(reversed, {5, 5}));  // either orientation (the painter's nonzero rule)
}

TEST(CanvasGeometry, BoxesUniteAndIntersect) {
  EXPECT_TRUE(intersects({0, 0, 10, 10}, {5, 5, 10, 10}));
  EXPECT_FALSE(intersects({0, 0, 10, 10}, {10, 0, 5, 5}));  // touching edges do not overlap
  const Rect u = united({0, 0, 10, 10}, {20, -5, 1, 1});
  EXPECT_DOUBLE_EQ(u.x, 0.0);
  EXPECT_DOUBLE_EQ(u.y, -5.0);
  EXPECT_DOUBLE_EQ(u.width, 21.0);
  EXPECT_DOUBLE_EQ(u.height, 15.0);
}

// A circle of radius 2 at (1, 1), seen at scale 10 about the origin (y up):
// a filled polygon of kCircleEdges edges on a circle of radius 20 px; an
// arrow is its one segment; a label has no outline.
TEST(CanvasGeometry, OutlinesAreTheShapesOnTheCanvas) {
  ViewTransform view;
  view.scale = 10.0;
  view.world_center = {0, 0};
  view.canvas_center = {100, 100};
  view.y_up = true;
  const auto circle = canvas_outline(Circle{{1, 1}, 2.0, LineStyle{}, Color{0, 0, 0, 1}}, view);
  ASSERT_TRUE(circle.has_value());
  ASSERT_EQ(circle->edges.size(), static_cast<std::size_t>(kCircleEdges));
  ASSERT_EQ(circle->areas.size(), 1u);
  for (const Edge& e : circle->edges) EXPECT_NEAR(std::abs(e.a - Point(110, 90)), 20.0, 1e-9);
  EXPECT_NEAR(circle->bounds.x, 90.0, 1e-9);
  EXPECT_NEAR(circle->bounds.width, 40.0, 1e-9);
  EXPECT_TRUE(lies_under(*circle, {105, 85, 10, 10}, true));    // inside the disc
  EXPECT_FALSE(lies_under(*circle, {105, 85, 10, 10}, false));  // not on its rim
  EXPECT_FALSE(lies_under(*circle, {200, 200, 10, 10}, true));
  const auto arrow = canvas_outline(ArrowShape{{0, 0}, {1, 0}, LineStyle{}}, view);
  ASSERT_TRUE(arrow.has_value());
  ASSERT_EQ(arrow->edges.size(), 1u);
  EXPECT_NEAR(std::abs(arrow->edges[0].b - Point(110, 100)), 0.0, 1e-12);
  Label label;
  label.text = "x";
  EXPECT_FALSE(canvas_outline(label, view).has_value());
}

}  // namespace
}  // namespace pita::render
