#include "lint/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/overloaded.hpp"
#include "render/painter.hpp"

namespace pita::lint {

namespace {

using render::ViewTransform;

// A circle as a polygon of this many edges.
constexpr int kCircleEdges = 48;

Rect empty_rect() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {inf, inf, -inf, -inf};  // united() with anything gives that thing
}

Rect box_of_points(const std::vector<Point>& points) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Point p : points) {
    x0 = std::min(x0, p.real());
    y0 = std::min(y0, p.imag());
    x1 = std::max(x1, p.real());
    y1 = std::max(y1, p.imag());
  }
  return {x0, y0, x1 - x0, y1 - y0};
}

void add_path(DataShape& shape, const std::vector<Point>& points, bool closed) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) shape.edges.push_back({points[i], points[i + 1]});
  if (closed && points.size() > 2) shape.edges.push_back({points.back(), points.front()});
}

std::vector<Point> on_canvas(const std::vector<Point>& world, const ViewTransform& view) {
  std::vector<Point> out;
  out.reserve(world.size());
  for (const Point p : world) out.push_back(view(p));
  return out;
}

void set_line(DataShape& data, const scene::LineStyle& line) {
  data.color = line.color;
  data.stroked = true;
  data.style = fmt::format("{} {:g}px{}", color_text(line.color), line.width,
                           line.dash.empty() ? "" : fmt::format(" dashed {}", fmt::join(line.dash, ",")));
}

// A shape's data on the canvas; nullopt for a label (a text).
std::optional<DataShape> data_shape(const render::Shape& shape, const ViewTransform& view) {
  DataShape data;
  const bool drawn = std::visit(
      overloaded{[&](const render::Polyline& s) {
                   if (s.points.size() < 2) return false;
                   add_path(data, on_canvas(s.points, view), s.closed);
                   set_line(data, s.line);
                   return true;
                 },
                 [&](const render::FilledPath& s) {
                   for (const auto& contour : s.contours) {
                     if (contour.size() < 3) continue;
                     std::vector<Point> points = on_canvas(contour, view);
                     add_path(data, points, true);
                     data.areas.push_back(std::move(points));
                   }
                   data.color = s.fill;
                   data.style = fmt::format("fill {}", color_text(s.fill));
                   if (s.outline) set_line(data, *s.outline);
                   return !data.edges.empty();
                 },
                 [&](const render::Circle& s) {
                   std::vector<Point> points;
                   const Point c = view(s.center);
                   const double r = s.radius * view.scale;
                   for (int k = 0; k < kCircleEdges; ++k) {
                     points.push_back(c + std::polar(r, 2.0 * M_PI * k / kCircleEdges));
                   }
                   add_path(data, points, true);
                   if (s.fill) data.areas.push_back(points);
                   set_line(data, s.line);
                   return true;
                 },
                 [&](const render::ArrowShape& s) {
                   data.edges.push_back({view(s.from), view(s.to)});
                   set_line(data, s.line);
                   return true;
                 },
                 [&](const render::Label&) { return false; },
                 [&](const render::Image& s) {
                   const auto corners = render::image_corners(s);
                   std::vector<Point> points = on_canvas({corners.begin(), corners.end()}, view);
                   add_path(data, points, true);
                   data.areas.push_back(std::move(points));
                   return true;
                 }},
      shape);
  if (!drawn) return std::nullopt;
  std::vector<Point> all;
  for (const Segment& e : data.edges) {
    all.push_back(e.a);
    all.push_back(e.b);
  }
  data.bounds = box_of_points(all);
  return data;
}

// The "type" of the layer at `pointer` ("/layers/3", "/panels/1/layers/0").
std::string layer_type_at(const scene::Scene& scene, const scene::Panel& panel, const std::string& pointer) {
  const std::size_t slash = pointer.rfind("/layers/");
  if (slash == std::string::npos) return "";
  std::size_t index = 0;
  try {
    index = std::stoul(pointer.substr(slash + 8));
  } catch (const std::exception&) {
    return "";
  }
  const bool own = slash > 0;  // the panel's own layers
  const bool arrows = std::holds_alternative<scene::KeyframeKeys>(panel.keys) ||
                      std::holds_alternative<scene::PointKeys>(panel.keys);
  if (arrows) {
    const auto& layers = own && panel.layers ? *panel.layers : scene.layers;
    return index < layers.size() ? std::string(scene::layer_type(layers[index])) : "";
  }
  const auto& layers = own && panel.pose_layers ? *panel.pose_layers : scene.pose_layers;
  return index < layers.size() ? std::string(scene::layer_type(layers[index])) : "";
}

std::string panel_name(const scene::Scene& scene, std::size_t i) {
  const std::string& title = scene.panels[i].title;
  if (scene.panels.size() == 1 && title.empty()) return "the figure";
  return title.empty() ? fmt::format("panel {}", i) : fmt::format("panel {} ({})", i, title);
}

}  // namespace

std::string color_text(const scene::Color& c) {
  const auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

bool intersects(const Rect& a, const Rect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

Rect united(const Rect& a, const Rect& b) {
  if (!(a.width >= 0.0)) return b;
  if (!(b.width >= 0.0)) return a;
  const double x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  const double x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
  return {x0, y0, x1 - x0, y1 - y0};
}

bool segment_meets(const Segment& s, const Rect& r) {
  // Liang-Barsky: clip the parameter range [0, 1] of a + u (b - a) to the box.
  double u0 = 0.0, u1 = 1.0;
  const double dx = s.b.real() - s.a.real(), dy = s.b.imag() - s.a.imag();
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {s.a.real() - r.x, r.x + r.width - s.a.real(), s.a.imag() - r.y, r.y + r.height - s.a.imag()};
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

FigureGeometry figure_geometry(const scene::Scene& scene, const render::Figure& figure) {
  const scene::Canvas& canvas = scene.canvas;
  FigureGeometry geometry;
  geometry.canvas = {0.0, 0.0, static_cast<double>(canvas.width), static_cast<double>(canvas.height)};
  if (!scene.title.empty()) {
    geometry.titles.push_back({render::text_ink_box(scene.title, canvas.font, render::kTitleSize,
                                                    render::scene_title_placement(canvas), render::is_markup(scene.title)),
                               "/title", scene.title, TextKind::title});
    geometry.title_cells.push_back(geometry.canvas);
  }
  for (std::size_t i = 0; i < figure.drawings.size(); ++i) {
    const scene::Panel& panel = scene.panels[i];
    const render::PanelPlacement& place = figure.placements[i];
    const render::Drawing& drawing = figure.drawings[i];
    if (!panel.title.empty()) {
      geometry.titles.push_back({render::text_ink_box(panel.title, canvas.font, render::kPanelTitleSize,
                                                      render::panel_title_placement(place),
                                                      render::is_markup(panel.title)),
                                 panel.pointer.empty() ? "/title" : panel.pointer + "/title", panel.title,
                                 TextKind::title});
      geometry.title_cells.push_back(place.cell);
    }
    PanelGeometry out;
    out.pointer = panel.pointer;
    out.name = panel_name(scene, i);
    out.area = render::drawing_area(place);
    out.plot = place.plot;
    std::map<std::string, std::string> types;  // of each layer pointer met
    for (const render::Item& item : drawing.items) {
      if (const auto* label = std::get_if<render::Label>(&item.shape)) {
        out.texts.push_back({render::text_ink_box(label->text, canvas.font, label->size,
                                                  render::label_placement(*label, place.transform),
                                                  render::is_markup(label->text)),
                             item.layer, label->text, TextKind::label});
        continue;
      }
      std::optional<DataShape> data = data_shape(item.shape, place.transform);
      if (!data) continue;
      auto [type, inserted] = types.try_emplace(item.layer);
      if (inserted) type->second = layer_type_at(scene, panel, item.layer);
      data->layer = item.layer;
      data->type = type->second;
      data->index = item.index;
      data->frame = item.index >= 0 && (data->type == "pattern" || data->type == "shapes");
      out.data.push_back(std::move(*data));
    }
    for (const render::Legend& legend : drawing.legends) {
      const render::LegendGeometry placed = render::legend_geometry(legend, out.area);
      Rect box = legend.swatches ? placed.box : empty_rect();
      for (const render::LegendRow& row : placed.rows) {
        const Rect ink = render::text_ink_box(row.entry->text, canvas.font, legend.size, row.text, false);
        out.texts.push_back({ink, legend.layer, row.entry->text, TextKind::legend});
        box = united(box, ink);
      }
      if (!placed.rows.empty()) out.legends.push_back({box, legend.layer});
    }
    geometry.panels.push_back(std::move(out));
  }
  return geometry;
}

}  // namespace pita::lint
