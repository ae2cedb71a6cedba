// Shapes as they land on the canvas, in canvas pixels: the edges and filled
// areas of each shape under a panel's view, and how they meet a box. What
// places "auto" labels (render/label_placement.hpp) and what `pita lint`
// measures (src/lint/), so that both see the same figure.
#pragma once

#include <optional>
#include <vector>

#include "render/drawing.hpp"
#include "render/layout.hpp"

namespace pita::render {

struct Edge {
  Point a, b;
};

// A shape's data on the canvas: its strokes and the edges of its fills, its
// filled areas (a text inside one is over it), and the box of its edges.
struct CanvasOutline {
  std::vector<Edge> edges;
  std::vector<std::vector<Point>> areas;
  Rect bounds;
};

// A circle as a polygon of this many edges.
inline constexpr int kCircleEdges = 48;

// nullopt for a label (a text) and for a shape with nothing to draw.
std::optional<CanvasOutline> canvas_outline(const Shape& shape, const ViewTransform& view);

// Whether the outline lies under the box: an edge crosses it, or (with
// `areas`) the box's centre is inside one of its filled areas.
bool lies_under(const CanvasOutline& outline, const Rect& box, bool areas);

// Boxes.
bool intersects(const Rect& a, const Rect& b);  // overlap (touching sides do not)
Rect united(const Rect& a, const Rect& b);      // an empty_rect() is nothing
Rect empty_rect();
Rect shrunk(const Rect& r, double by);  // by `by` on every side, never below 0
bool contains(const Rect& outer, const Rect& inner);
bool edge_meets(const Edge& e, const Rect& r);            // any point of e inside r
bool inside(const std::vector<Point>& contour, Point p);  // nonzero winding

}  // namespace pita::render
