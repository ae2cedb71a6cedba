#include "render/carried_shapes.hpp"

namespace pita::render {

Affine2 image_placement(const scene::ShapeOutline& image, bool y_up) {
  // points: (x0, y0), (x1, y0), (x1, y1), (x0, y1) (scene/figure.hpp).
  const Point low = image.points[0], high = image.points[2];
  const double sx = (high.real() - low.real()) / image.image->width;
  const double sy = (high.imag() - low.imag()) / image.image->height;
  Affine2 placement;
  placement.L << sx, 0.0, 0.0, y_up ? -sy : sy;
  placement.b << low.real(), y_up ? high.imag() : low.imag();
  return placement;
}

std::vector<Shape> carried_shapes(const std::vector<scene::ShapeOutline>& shapes, const Affine2& map,
                                  const scene::ShapesLayer& layer, bool y_up, double fade) {
  std::vector<Shape> drawn;
  drawn.reserve(shapes.size());
  for (const scene::ShapeOutline& shape : shapes) {
    if (shape.image) {
      drawn.emplace_back(Image{shape.image->path, shape.image->given, shape.image->width, shape.image->height,
                               compose(map, image_placement(shape, y_up)), fade});
      continue;
    }
    LineStyle line = layer.line;
    if (shape.color) line.color = *shape.color;
    line.opacity *= fade;
    std::vector<Point> points;
    points.reserve(shape.points.size());
    for (const Point p : shape.points) points.push_back(pita::apply(map, p));
    if (layer.fill && shape.closed) {
      FilledPath filled;
      filled.contours.push_back(std::move(points));
      filled.fill = *layer.fill;
      filled.opacity = layer.fill_opacity * fade;
      filled.outline = line;
      drawn.emplace_back(std::move(filled));
    } else {
      drawn.emplace_back(Polyline{std::move(points), shape.closed, line});
    }
  }
  return drawn;
}

}  // namespace pita::render
