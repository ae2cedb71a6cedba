#include "render/figure_digest.hpp"

#include <variant>

#include "core/fnv1a.hpp"
#include "core/overloaded.hpp"

namespace pita::render {

namespace {

class Digest {
 public:
  void add(double x) { hash_.add(x); }
  void add(std::string_view text) {
    add(static_cast<double>(text.size()));
    hash_.add(text);
  }
  void add(const Point& p) {
    add(p.real());
    add(p.imag());
  }
  void add(const Color& c) {
    for (const double x : {c.r, c.g, c.b, c.a}) add(x);
  }
  void add(const LineStyle& line) {
    add(line.color);
    add(line.width);
    add(line.opacity);
    add(static_cast<double>(line.dash.size()));
    for (const double d : line.dash) add(d);
  }
  void add(const std::vector<Point>& points) {
    add(static_cast<double>(points.size()));
    for (const Point& p : points) add(p);
  }
  void add(const Rect& r) {
    for (const double x : {r.x, r.y, r.width, r.height}) add(x);
  }
  void add(const Shape& shape) {
    add(static_cast<double>(shape.index()));
    std::visit(overloaded{[&](const Polyline& s) {
                            add(s.points);
                            add(s.closed ? 1.0 : 0.0);
                            add(s.line);
                          },
                          [&](const FilledPath& s) {
                            add(static_cast<double>(s.contours.size()));
                            for (const auto& contour : s.contours) add(contour);
                            add(s.fill);
                            add(s.opacity);
                            add(s.outline ? 1.0 : 0.0);
                            if (s.outline) add(*s.outline);
                          },
                          [&](const Circle& s) {
                            add(s.center);
                            add(s.radius);
                            add(s.line);
                            add(s.fill ? 1.0 : 0.0);
                            if (s.fill) add(*s.fill);
                          },
                          [&](const ArrowShape& s) {
                            add(s.from);
                            add(s.to);
                            add(s.line);
                          },
                          [&](const Label& s) {
                            add(s.text);
                            add(s.at);
                            add(s.size);
                            add(s.color);
                            add(s.shift);
                          },
                          [&](const Image& s) {
                            add(s.path);
                            for (const double x : {s.to_world.L(0, 0), s.to_world.L(0, 1), s.to_world.L(1, 0),
                                                   s.to_world.L(1, 1), s.to_world.b(0), s.to_world.b(1), s.opacity}) {
                              add(x);
                            }
                          }},
               shape);
  }
  std::uint64_t value() const { return hash_.value(); }

 private:
  Fnv1a hash_;
};

}  // namespace

std::uint64_t figure_digest(const Figure& figure) {
  Digest digest;
  for (const Drawing& drawing : figure.drawings) {
    digest.add(static_cast<double>(drawing.items.size()));
    for (const Item& item : drawing.items) digest.add(item.shape);
    for (const Legend& legend : drawing.legends) {
      digest.add(legend.size);
      for (const LegendEntry& entry : legend.entries) {
        digest.add(entry.color);
        digest.add(entry.text);
      }
    }
  }
  for (const PanelPlacement& place : figure.placements) {
    digest.add(place.cell);
    digest.add(place.plot);
    digest.add(place.view.min);
    digest.add(place.view.max);
  }
  return digest.value();
}

}  // namespace pita::render
