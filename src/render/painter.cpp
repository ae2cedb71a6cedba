#include "render/painter.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "render/image_cache.hpp"
#include "render/pango_library.hpp"

namespace pita::render {

namespace {

void set_color(cairo_t* cr, const Color& c, double opacity) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a * opacity); }

void set_line(cairo_t* cr, const LineStyle& line) {
  set_color(cr, line.color, line.opacity);
  cairo_set_line_width(cr, line.width);
  cairo_set_dash(cr, line.dash.empty() ? nullptr : line.dash.data(), static_cast<int>(line.dash.size()), 0.0);
}

void move_to(cairo_t* cr, Point p) { cairo_move_to(cr, p.real(), p.imag()); }
void line_to(cairo_t* cr, Point p) { cairo_line_to(cr, p.real(), p.imag()); }

struct ShapePainter {
  cairo_t* cr;
  const ViewTransform& view;
  const std::string& font;

  void operator()(const Polyline& s) const {
    if (s.points.size() < 2) return;
    move_to(cr, view(s.points.front()));
    for (std::size_t i = 1; i < s.points.size(); ++i) line_to(cr, view(s.points[i]));
    if (s.closed) cairo_close_path(cr);
    set_line(cr, s.line);
    cairo_stroke(cr);
  }

  void operator()(const FilledPath& s) const {
    for (const auto& contour : s.contours) {
      if (contour.size() < 3) continue;
      move_to(cr, view(contour.front()));
      for (std::size_t i = 1; i < contour.size(); ++i) line_to(cr, view(contour[i]));
      cairo_close_path(cr);
    }
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    set_color(cr, s.fill, s.opacity);
    if (s.outline) {
      cairo_fill_preserve(cr);
      set_line(cr, *s.outline);
      cairo_stroke(cr);
    } else {
      cairo_fill(cr);
    }
  }

  void operator()(const Circle& s) const {
    const Point c = view(s.center);
    cairo_new_sub_path(cr);
    cairo_arc(cr, c.real(), c.imag(), s.radius * view.scale, 0.0, 2.0 * std::numbers::pi);
    if (s.fill) {
      set_color(cr, *s.fill, s.line.opacity);
      cairo_fill_preserve(cr);
    }
    set_line(cr, s.line);
    cairo_stroke(cr);
  }

  void operator()(const ArrowShape& s) const {
    const Point from = view(s.from), to = view(s.to);
    const double length = std::abs(to - from);
    const double head = std::max(kHeadMin, kHeadPerWidth * s.line.width);
    set_line(cr, s.line);
    if (length > 0.0) {
      const Point direction = (to - from) / length;
      const double h = std::min(head, length);
      const Point base = to - direction * h;
      move_to(cr, from);
      line_to(cr, base + direction * (0.3 * h));  // under the head, no gap
      cairo_stroke(cr);
      const Point side = direction * Point{0.0, 1.0} * (0.4 * h);
      move_to(cr, to);
      line_to(cr, base + side);
      line_to(cr, base - side);
      cairo_close_path(cr);
      cairo_fill(cr);
    }
  }

  void operator()(const Label& s) const {
    const TextPlacement at = label_placement(s, view);
    paint_text(cr, s.text, font, s.size, s.color, at.x, at.y, at.align, is_markup(s.text));
  }
  void operator()(const Image& s) const {
    const Affine2 to_canvas = image_to_canvas(s, view);
    if (!(std::abs(to_canvas.L.determinant()) > 0.0)) return;  // collapsed to a line
    cairo_surface_t* pixels = cached_image(s.path, s.name);
    cairo_save(cr);
    cairo_matrix_t matrix;
    cairo_matrix_init(&matrix, to_canvas.L(0, 0), to_canvas.L(1, 0), to_canvas.L(0, 1), to_canvas.L(1, 1),
                      to_canvas.b(0), to_canvas.b(1));
    cairo_transform(cr, &matrix);
    cairo_rectangle(cr, 0.0, 0.0, s.width, s.height);
    cairo_clip(cr);
    cairo_set_source_surface(cr, pixels, 0.0, 0.0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
    cairo_paint_with_alpha(cr, s.opacity);
    cairo_restore(cr);
  }
};

void unref(gpointer object) { pango().object_unref(object); }

void paint_legend(cairo_t* cr, const Legend& legend, const Rect& area, const std::string& font) {
  for (const LegendRow& row : legend_geometry(legend, area).rows) {
    if (legend.swatches) {
      move_to(cr, row.swatch_from);
      line_to(cr, row.swatch_to);
      set_line(cr, LineStyle{row.entry->color, 2.0, 1.0, row.entry->dash});
      cairo_stroke(cr);
    }
    paint_text(cr, row.entry->text, font, legend.size, row.text_color, row.text.x, row.text.y, row.text.align);
  }
}

}  // namespace

Affine2 image_to_canvas(const Image& image, const ViewTransform& view) {
  // canvas = C (world - world_center) + canvas_center, C = diag(s, -s) (y up) or diag(s, s).
  Affine2 to_canvas;
  to_canvas.L << view.scale, 0.0, 0.0, view.y_up ? -view.scale : view.scale;
  to_canvas.b << view.canvas_center.real() - view.scale * view.world_center.real(),
      view.canvas_center.imag() + (view.y_up ? view.scale : -view.scale) * view.world_center.imag();
  return compose(to_canvas, image.to_world);
}

LegendGeometry legend_geometry(const Legend& legend, const Rect& area) {
  const double line_height = kLegendLineHeight * legend.size, swatch = 2.0 * legend.size;
  const double height = legend_height(legend);
  const bool right = legend.corner == scene::LegendLayer::Corner::top_right ||
                     legend.corner == scene::LegendLayer::Corner::bottom_right;
  const bool bottom = legend.corner == scene::LegendLayer::Corner::bottom_left ||
                      legend.corner == scene::LegendLayer::Corner::bottom_right;
  const double pad = kLegendPad, width = swatch + 9.0 * legend.size;
  const double x = right ? area.x + area.width - width - pad : area.x + pad;
  const double top = bottom ? area.y + area.height - height - pad : area.y + pad;
  LegendGeometry geometry;
  geometry.box = {x, top, width, height};
  double y = top;
  for (const LegendEntry& entry : legend.entries) {
    const double mid = y + 0.5 * line_height;
    LegendRow row;
    row.entry = &entry;
    if (legend.swatches) {  // a swatch, then the text in ink
      row.swatch_from = {x, mid};
      row.swatch_to = {x + swatch, mid};
      row.text = {x + swatch + 5.0, mid - 0.65 * legend.size, TextAlign::left};
      row.text_color = Color{0.1, 0.1, 0.1, 1.0};
    } else {  // text only, aligned on the corner's side, in the entry's colour
      row.text = {right ? area.x + area.width - pad : area.x + pad, mid - 0.65 * legend.size,
                  right ? TextAlign::right : TextAlign::left};
      row.text_color = entry.color;
    }
    geometry.rows.push_back(row);
    y += line_height;
  }
  return geometry;
}

TextPlacement label_placement(const Label& label, const ViewTransform& view) {
  const Point at = view(label.at) + label.shift;
  return {at.real(), at.imag() - 0.6 * label.size, TextAlign::left};
}

TextPlacement scene_title_placement(const scene::Canvas& canvas) {
  return {0.5 * canvas.width, 0.5 * (kTitleBand - 1.3 * kTitleSize), TextAlign::center};
}

TextPlacement panel_title_placement(const PanelPlacement& placement) {
  return {placement.title.x + 0.5 * placement.title.width,
          placement.title.y + 0.5 * (kPanelTitleBand - 1.3 * kPanelTitleSize), TextAlign::center};
}

Rect drawing_area(const PanelPlacement& placement) {
  return {placement.cell.x, placement.cell.y + placement.title.height, placement.cell.width,
          placement.cell.height - placement.title.height};
}

bool is_markup(const std::string& text) {
  if (text.find('<') == std::string::npos) return false;
  return pango().parse_markup(text.c_str(), static_cast<int>(text.size()), 0, nullptr, nullptr, nullptr, nullptr) !=
         FALSE;
}

namespace {

using LayoutPtr = std::unique_ptr<PangoLayout, decltype(&unref)>;

// The layout paint_text draws and text_ink_box measures: unhinted, so that
// its size does not depend on the surface.
LayoutPtr text_layout(cairo_t* cr, const std::string& text, const std::string& font, double size, bool markup) {
  const PangoLibrary& library = pango();
  LayoutPtr layout(library.cairo_create_layout(cr), &unref);
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  library.cairo_context_set_font_options(library.layout_get_context(layout.get()), options);
  cairo_font_options_destroy(options);
  library.layout_context_changed(layout.get());
  PangoFontDescription* description = library.font_description_from_string(font.c_str());
  library.font_description_set_absolute_size(description, size * PANGO_SCALE);
  library.layout_set_font_description(layout.get(), description);
  library.font_description_free(description);
  if (markup) {
    library.layout_set_markup(layout.get(), text.c_str(), static_cast<int>(text.size()));
  } else {
    library.layout_set_text(layout.get(), text.c_str(), static_cast<int>(text.size()));
  }
  return layout;
}

double layout_left(PangoLayout* layout, const TextPlacement& at) {
  int width = 0, height = 0;
  pango().layout_get_pixel_size(layout, &width, &height);
  return at.align == TextAlign::left ? at.x : at.align == TextAlign::center ? at.x - 0.5 * width : at.x - width;
}

}  // namespace

void paint_text(cairo_t* cr, const std::string& text, const std::string& font, double size, const Color& color,
                double x, double y, TextAlign align, bool markup) {
  const LayoutPtr layout = text_layout(cr, text, font, size, markup);
  set_color(cr, color, 1.0);
  cairo_move_to(cr, layout_left(layout.get(), {x, y, align}), y);
  pango().cairo_show_layout(cr, layout.get());
  cairo_new_path(cr);
}

Rect text_ink_box(const std::string& text, const std::string& font, double size, const TextPlacement& at, bool markup) {
  // A context of its own per thread, on a 1x1 surface: the layout only needs its font options.
  thread_local const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> measuring = [] {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
    cairo_t* cr = cairo_create(surface);
    cairo_surface_destroy(surface);  // the context holds it
    return std::unique_ptr<cairo_t, decltype(&cairo_destroy)>(cr, &cairo_destroy);
  }();
  const LayoutPtr layout = text_layout(measuring.get(), text, font, size, markup);
  PangoRectangle ink, logical;
  pango().layout_get_pixel_extents(layout.get(), &ink, &logical);
  return {layout_left(layout.get(), at) + ink.x, at.y + ink.y, static_cast<double>(ink.width),
          static_cast<double>(ink.height)};
}

void paint_drawing(cairo_t* cr, const Drawing& drawing, const PanelPlacement& placement, const std::string& font,
                   const ItemRange& range) {
  cairo_save(cr);
  const Rect area = drawing_area(placement);
  cairo_rectangle(cr, area.x, area.y, area.width, area.height);
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  const ShapePainter painter{cr, placement.transform, font};
  const std::size_t to = std::min(range.to, drawing.items.size());
  for (std::size_t i = range.from; i < to; ++i) std::visit(painter, drawing.items[i].shape);
  if (range.legends) {
    for (const Legend& legend : drawing.legends) paint_legend(cr, legend, drawing_area(placement), font);
  }
  cairo_restore(cr);
}

}  // namespace pita::render
