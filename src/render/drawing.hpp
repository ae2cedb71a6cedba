// What a figure draws, as numbers: shapes in world coordinates (the plane of
// the keyframes), before any view transform or cairo call. render/ builds a
// Drawing per panel (panel_drawing.hpp) and then paints it (painter.hpp); the
// tests check the geometry here, and golden files record it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/affine2.hpp"
#include "core/arrow.hpp"
#include "scene/figure.hpp"

namespace pita::render {

using scene::Color;
using scene::LineStyle;

// An open or closed polyline: pattern frames, trajectories, spirals, outlines.
struct Polyline {
  std::vector<Point> points;
  bool closed = false;
  LineStyle line;
  friend bool operator==(const Polyline&, const Polyline&) = default;
};

// Filled closed contours with the nonzero rule (stroke strips, banner glyphs).
struct FilledPath {
  std::vector<std::vector<Point>> contours;
  Color fill;
  double opacity = 1.0;
  std::optional<LineStyle> outline;
  friend bool operator==(const FilledPath&, const FilledPath&) = default;
};

// A circle (discrepancy), radius in world units.
struct Circle {
  Point center;
  double radius = 0.0;
  LineStyle line;
  std::optional<Color> fill;
  friend bool operator==(const Circle&, const Circle&) = default;
};

// A segment with an arrowhead at `to` (keyframes); the head has a fixed size
// in pixels, so it is sized by the painter.
struct ArrowShape {
  Point from;
  Point to;
  LineStyle line;
  friend bool operator==(const ArrowShape&, const ArrowShape&) = default;
};

// A text anchored at a point of the plane (labels); size in pixels. With
// `avoid_data` ("place": "auto"), the figure moves it around its point to
// where it covers no data: `shift`, in canvas pixels, from where it starts
// at its point (render/label_placement.hpp).
struct Label {
  std::string text;
  Point at;
  double size = 12.0;
  Color color;
  bool avoid_data = false;
  Point shift{0.0, 0.0};
  friend bool operator==(const Label&, const Label&) = default;
};

// A raster image (a PNG of "shapes", PITA Sec. 7.1) placed on the plane:
// pixel (u, v) of the file, v down, lands at to_world(u, v). The painter
// reads the file through cairo (render/image_cache.hpp).
struct Image {
  std::string path;  // the file to read
  std::string name;  // as the scene spells it
  int width = 0, height = 0;
  Affine2 to_world;  // pixel coordinates -> world
  double opacity = 1.0;
  friend bool operator==(const Image& a, const Image& b) {
    return a.path == b.path && a.name == b.name && a.width == b.width && a.height == b.height &&
           a.to_world.L == b.to_world.L && a.to_world.b == b.to_world.b && a.opacity == b.opacity;
  }
};

using Shape = std::variant<Polyline, FilledPath, Circle, ArrowShape, Label, Image>;

// A shape and where it comes from: the JSON Pointer of its layer
// ("/layers/2") and the frame (or keyframe) index it belongs to, -1 if none.
struct Item {
  std::string layer;
  int index = -1;
  Shape shape;
  // Drawn anew at each frame of an animation (the frame D(t), the shapes it
  // carries, a moving pattern); false: the same in every frame (the animated
  // SVG draws it once).
  bool moving = false;
  friend bool operator==(const Item&, const Item&) = default;
};

// The legend of a panel, painted in pixel space.
struct LegendEntry {
  Color color;
  std::string text;
  std::vector<double> dash = {};  // the swatch's dash pattern (a dashed trajectory); empty = solid
};
struct Legend {
  scene::LegendLayer::Corner corner = scene::LegendLayer::Corner::top_left;
  double size = 11.0;
  std::vector<LegendEntry> entries;
  bool swatches = true;    // false: text only, flush with the corner's side (a "measures" layer)
  std::string layer = {};  // the JSON Pointer of the layer that prints it (what `pita lint` names)
};

struct Drawing {
  std::vector<Item> items;
  std::vector<Legend> legends;
};

// The smallest box holding every point of the drawing (circles and labels by
// their centre or anchor only); nullopt for an empty drawing.
std::optional<scene::Box> bounds(const Drawing& drawing);

// Turns a closed contour counter-clockwise (in the plane's own orientation),
// so that contours filled together by the nonzero rule add up instead of
// cancelling; returns twice its area (0: degenerate, left as it is).
double turn_counter_clockwise(std::vector<Point>& contour);

// The four corners of the rectangle from (x, y), `width` by `height`, in
// order (a table's cell, a tree's box).
std::vector<Point> rectangle_corners(double x, double y, double width, double height);

// The image's corners on the plane: pixels (0, 0), (w, 0), (w, h), (0, h).
std::array<Point, 4> image_corners(const Image& image);

// True when every coordinate and radius of the drawing is finite.
bool is_finite(const Drawing& drawing);

}  // namespace pita::render
