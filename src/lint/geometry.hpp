// What the lint looks at: a figure as it lands on the canvas, in canvas
// pixels, before anything is painted. Every text is a box of ink (measured
// with the same Pango layout the painter draws), every stroke an edge,
// every fill a contour, each tagged with the JSON Pointer it comes from.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "render/figure.hpp"
#include "scene/scene.hpp"

namespace pita::lint {

using render::Rect;

enum class TextKind { title, label, legend };

struct TextBox {
  Rect box;           // its ink, canvas pixels
  std::string owner;  // "/title", "/panels/2/title", "/layers/3"
  std::string text;
  TextKind kind = TextKind::label;
};

struct Segment {
  Point a, b;
};

// One shape of a layer's data (not text), on the canvas.
struct DataShape {
  std::string layer;  // the layer's pointer
  std::string type;   // its "type" ("pattern", "poses", ...)
  int index = -1;     // its frame or keyframe, -1 if none
  std::vector<Segment> edges;                // strokes, and the edges of fills
  std::vector<std::vector<Point>> areas;     // filled contours and images (a text inside one is over data)
  Rect bounds;        // of its edges and areas
  scene::Color color;     // of its stroke (a fill without outline: of the fill)
  std::string style;      // its colour, width and dash, as text: what tells series apart
  bool stroked = false;   // drawn with a line (not only filled)
  bool frame = false;  // a frame of a pattern (its one segment) or a shape carried to a frame
};

struct LegendBox {
  Rect box;
  std::string layer;
};

struct PanelGeometry {
  std::string pointer;  // the panel's ("" for a scene without "panels")
  std::string name;     // for messages: "panel 2 (P6 La-LP)"
  Rect area;            // where its drawing is painted (and clipped to)
  Rect plot;            // the area less its margins: what the view is fitted into
  std::vector<DataShape> data;
  std::vector<TextBox> texts;  // labels and legend lines
  std::vector<LegendBox> legends;
};

struct FigureGeometry {
  Rect canvas;
  std::vector<TextBox> titles;  // the scene's and the panels' titles
  std::vector<Rect> title_cells;  // where each title may go (the canvas's band, a panel's cell)
  std::vector<PanelGeometry> panels;
};

FigureGeometry figure_geometry(const scene::Scene& scene, const render::Figure& figure);

// "#rrggbb".
std::string color_text(const scene::Color& color);

// Boxes.
bool intersects(const Rect& a, const Rect& b);
Rect united(const Rect& a, const Rect& b);
bool segment_meets(const Segment& s, const Rect& r);  // any point of s inside r
bool inside(const std::vector<Point>& contour, Point p);  // nonzero winding

}  // namespace pita::lint
