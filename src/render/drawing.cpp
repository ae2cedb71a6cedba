#include "render/drawing.hpp"

#include <algorithm>
#include <cmath>

namespace pita::render {

namespace {

struct BoundsBuilder {
  bool empty = true;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  void add(Point p) {
    if (empty) {
      x0 = x1 = p.real();
      y0 = y1 = p.imag();
      empty = false;
      return;
    }
    x0 = std::min(x0, p.real());
    x1 = std::max(x1, p.real());
    y0 = std::min(y0, p.imag());
    y1 = std::max(y1, p.imag());
  }
  void operator()(const Polyline& s) {
    for (Point p : s.points) add(p);
  }
  void operator()(const FilledPath& s) {
    for (const auto& contour : s.contours) {
      for (Point p : contour) add(p);
    }
  }
  // Discrepancy circles are annotations: a near-singular frame can make one
  // huge, and fitting it would shrink the figure to a dot. Only the centre
  // counts; the circle may leave the panel (it is clipped to the panel).
  void operator()(const Circle& s) { add(s.center); }
  void operator()(const ArrowShape& s) {
    add(s.from);
    add(s.to);
  }
  void operator()(const Label& s) { add(s.at); }
  void operator()(const Image& s) {
    for (const Point corner : image_corners(s)) add(corner);
  }
};

bool finite(Point p) { return std::isfinite(p.real()) && std::isfinite(p.imag()); }

struct FiniteCheck {
  bool operator()(const Polyline& s) const { return std::all_of(s.points.begin(), s.points.end(), finite); }
  bool operator()(const FilledPath& s) const {
    return std::all_of(s.contours.begin(), s.contours.end(),
                       [](const auto& contour) { return std::all_of(contour.begin(), contour.end(), finite); });
  }
  bool operator()(const Circle& s) const { return finite(s.center) && std::isfinite(s.radius); }
  bool operator()(const ArrowShape& s) const { return finite(s.from) && finite(s.to); }
  bool operator()(const Label& s) const { return finite(s.at); }
  bool operator()(const Image& s) const {
    const auto corners = image_corners(s);
    return s.to_world.L.allFinite() && s.to_world.b.allFinite() && std::all_of(corners.begin(), corners.end(), finite);
  }
};

}  // namespace

std::array<Point, 4> image_corners(const Image& image) {
  const double w = image.width, h = image.height;
  return {pita::apply(image.to_world, Point{0.0, 0.0}), pita::apply(image.to_world, Point{w, 0.0}),
          pita::apply(image.to_world, Point{w, h}), pita::apply(image.to_world, Point{0.0, h})};
}

std::optional<scene::Box> bounds(const Drawing& drawing) {
  BoundsBuilder builder;
  for (const Item& item : drawing.items) std::visit(builder, item.shape);
  if (builder.empty) return std::nullopt;
  return scene::Box{{builder.x0, builder.y0}, {builder.x1, builder.y1}};
}

bool is_finite(const Drawing& drawing) {
  return std::all_of(drawing.items.begin(), drawing.items.end(),
                     [](const Item& item) { return std::visit(FiniteCheck{}, item.shape); });
}

double turn_counter_clockwise(std::vector<Point>& contour) {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < contour.size(); ++i) {
    const Point a = contour[i], b = contour[(i + 1) % contour.size()];
    twice_area += a.real() * b.imag() - b.real() * a.imag();
  }
  if (twice_area < 0.0) std::reverse(contour.begin(), contour.end());
  return std::abs(twice_area);
}

std::vector<Point> rectangle_corners(double x, double y, double width, double height) {
  return {{x, y}, {x + width, y}, {x + width, y + height}, {x, y + height}};
}

}  // namespace pita::render
