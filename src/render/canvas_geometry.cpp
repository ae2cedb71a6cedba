#include "render/canvas_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/overloaded.hpp"

namespace pita::render {

namespace {

Rect box_of_edges(const std::vector<Edge>& edges) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Edge& e : edges) {
    for (const Point p : {e.a, e.b}) {
      x0 = std::min(x0, p.real());
      y0 = std::min(y0, p.imag());
      x1 = std::max(x1, p.real());
      y1 = std::max(y1, p.imag());
    }
  }
  return {x0, y0, x1 - x0, y1 - y0};
}

void add_path(CanvasOutline& out, const std::vector<Point>& points, bool closed) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) out.edges.push_back({points[i], points[i + 1]});
  if (closed && points.size() > 2) out.edges.push_back({points.back(), points.front()});
}

std::vector<Point> on_canvas(const std::vector<Point>& world, const ViewTransform& view) {
  std::vector<Point> out;
  out.reserve(world.size());
  for (const Point p : world) out.push_back(view(p));
  return out;
}

}  // namespace

std::optional<CanvasOutline> canvas_outline(const Shape& shape, const ViewTransform& view) {
  CanvasOutline out;
  std::visit(overloaded{[&](const Polyline& s) {
                          if (s.points.size() >= 2) add_path(out, on_canvas(s.points, view), s.closed);
                        },
                        [&](const FilledPath& s) {
                          for (const auto& contour : s.contours) {
                            if (contour.size() < 3) continue;
                            std::vector<Point> points = on_canvas(contour, view);
                            add_path(out, points, true);
                            out.areas.push_back(std::move(points));
                          }
                        },
                        [&](const Circle& s) {
                          std::vector<Point> points;
                          const Point c = view(s.center);
                          const double r = s.radius * view.scale;
                          for (int k = 0; k < kCircleEdges; ++k) {
                            points.push_back(c + std::polar(r, 2.0 * std::numbers::pi * k / kCircleEdges));
                          }
                          add_path(out, points, true);
                          if (s.fill) out.areas.push_back(points);
                        },
                        [&](const ArrowShape& s) {
                          out.edges.push_back({view(s.from), view(s.to)});
                        },
                        [&](const Label&) {},
                        [&](const Image& s) {
                          const auto corners = image_corners(s);
                          std::vector<Point> points = on_canvas({corners.begin(), corners.end()}, view);
                          add_path(out, points, true);
                          out.areas.push_back(std::move(points));
                        }},
             shape);
  if (out.edges.empty()) return std::nullopt;
  out.bounds = box_of_edges(out.edges);
  return out;
}

bool lies_under(const CanvasOutline& outline, const Rect& box, bool areas) {
  const Rect& b = outline.bounds;
  if (!intersects({b.x - 0.5, b.y - 0.5, b.width + 1.0, b.height + 1.0}, box)) return false;
  for (const Edge& e : outline.edges) {
    if (edge_meets(e, box)) return true;
  }
  if (!areas) return false;
  const Point centre{box.x + 0.5 * box.width, box.y + 0.5 * box.height};
  return std::any_of(outline.areas.begin(), outline.areas.end(),
                     [&](const std::vector<Point>& area) { return inside(area, centre); });
}

bool intersects(const Rect& a, const Rect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

Rect empty_rect() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {inf, inf, -inf, -inf};  // united() with anything gives that thing
}

Rect united(const Rect& a, const Rect& b) {
  if (!(a.width >= 0.0)) return b;
  if (!(b.width >= 0.0)) return a;
  const double x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  const double x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
  return {x0, y0, x1 - x0, y1 - y0};
}

Rect shrunk(const Rect& r, double by) {
  return {r.x + by, r.y + by, std::max(r.width - 2 * by, 0.0), std::max(r.height - 2 * by, 0.0)};
}

bool contains(const Rect& outer, const Rect& inner) {
  return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
}

bool edge_meets(const Edge& e, const Rect& r) {
  // Liang-Barsky: clip the parameter range [0, 1] of a + u (b - a) to the box.
  double u0 = 0.0, u1 = 1.0;
  const double dx = e.b.real() - e.a.real(), dy = e.b.imag() - e.a.imag();
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {e.a.real() - r.x, r.x + r.width - e.a.real(), e.a.imag() - r.y, r.y + r.height - e.a.imag()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;  // parallel to this side, outside it
      continue;
    }
    const double u = q[k] / p[k];
    if (p[k] < 0.0) {
      u0 = std::max(u0, u);
    } else {
      u1 = std::min(u1, u);
    }
    if (u0 > u1) return false;
  }
  return true;
}

bool inside(const std::vector<Point>& contour, Point p) {
  int winding = 0;
  for (std::size_t i = 0; i < contour.size(); ++i) {
    const Point a = contour[i], b = contour[(i + 1) % contour.size()];
    const double cross = (b.real() - a.real()) * (p.imag() - a.imag()) - (p.real() - a.real()) * (b.imag() - a.imag());
    if (a.imag() <= p.imag()) {
      if (b.imag() > p.imag() && cross > 0.0) ++winding;
    } else if (b.imag() <= p.imag() && cross < 0.0) {
      --winding;
    }
  }
  return winding != 0;
}

}  // namespace pita::render
