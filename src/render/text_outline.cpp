#include "render/text_outline.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <cairo.h>

#include "render/cairo_handles.hpp"
#include "render/pango_library.hpp"

namespace pita::render {

namespace {

// Text is laid out at this size (pixels); only proportions matter afterwards.
constexpr double kLayoutSize = 200.0;

template <typename T, void (*Free)(T*)>
struct Deleter {
  void operator()(T* p) const { Free(p); }
};
using PathPtr = std::unique_ptr<cairo_path_t, Deleter<cairo_path_t, cairo_path_destroy>>;
void unref_layout(PangoLayout* layout) { pango().object_unref(layout); }
using LayoutPtr = std::unique_ptr<PangoLayout, Deleter<PangoLayout, unref_layout>>;
void free_font_description(PangoFontDescription* description) { pango().font_description_free(description); }
using FontPtr = std::unique_ptr<PangoFontDescription, Deleter<PangoFontDescription, free_font_description>>;
using OptionsPtr = std::unique_ptr<cairo_font_options_t, Deleter<cairo_font_options_t, cairo_font_options_destroy>>;

// Appends the edge a -> b, split into pieces no longer than max_edge.
void add_edge(std::vector<Point>& contour, Point a, Point b, double max_edge) {
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(b - a) / max_edge)));
  for (int k = 1; k <= pieces; ++k) contour.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
}

}  // namespace

TextOutline text_outline(const std::string& text, const std::string& font) {
  SurfacePtr surface(cairo_recording_surface_create(CAIRO_CONTENT_ALPHA, nullptr));
  ContextPtr cr(cairo_create(surface.get()));
  const PangoLibrary& library = pango();
  LayoutPtr layout(library.cairo_create_layout(cr.get()));
  // Unhinted outlines: the same shapes at every size and on every surface.
  OptionsPtr options(cairo_font_options_create());
  cairo_font_options_set_hint_style(options.get(), CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
  library.cairo_context_set_font_options(library.layout_get_context(layout.get()), options.get());
  library.layout_context_changed(layout.get());

  FontPtr description(library.font_description_from_string(font.c_str()));
  library.font_description_set_absolute_size(description.get(), kLayoutSize * PANGO_SCALE);
  library.layout_set_font_description(layout.get(), description.get());
  library.layout_set_text(layout.get(), text.c_str(), static_cast<int>(text.size()));

  PangoRectangle ink, logical;
  library.layout_get_extents(layout.get(), &ink, &logical);
  TextOutline outline;
  outline.left = static_cast<double>(ink.x) / PANGO_SCALE;
  outline.right = static_cast<double>(ink.x + ink.width) / PANGO_SCALE;
  outline.top = static_cast<double>(logical.y) / PANGO_SCALE;
  outline.bottom = static_cast<double>(logical.y + logical.height) / PANGO_SCALE;
  const double height = outline.bottom - outline.top;
  if (!(outline.right > outline.left) || !(height > 0.0)) return outline;  // nothing visible

  library.cairo_layout_path(cr.get(), layout.get());
  cairo_set_tolerance(cr.get(), kBannerTolerance * height);
  PathPtr path(cairo_copy_path_flat(cr.get()));
  const double max_edge = kBannerMaxEdge * height;
  std::vector<Point> contour;
  Point start{}, current{};
  const auto finish = [&] {
    if (contour.size() >= 3) outline.contours.push_back(std::move(contour));
    contour.clear();
  };
  for (int i = 0; i < path->num_data; i += path->data[i].header.length) {
    const cairo_path_data_t* data = &path->data[i];
    switch (data->header.type) {
      case CAIRO_PATH_MOVE_TO:
        finish();
        start = current = {data[1].point.x, data[1].point.y};
        contour.push_back(start);
        break;
      case CAIRO_PATH_LINE_TO: {
        const Point next{data[1].point.x, data[1].point.y};
        add_edge(contour, current, next, max_edge);
        current = next;
        break;
      }
      case CAIRO_PATH_CLOSE_PATH:
        if (current != start) add_edge(contour, current, start, max_edge);
        if (!contour.empty()) contour.pop_back();  // the closing point repeats the first
        current = start;
        finish();
        break;
      case CAIRO_PATH_CURVE_TO:  // not produced by cairo_copy_path_flat
        break;
    }
  }
  finish();
  // The ink box from the outline itself (pango's is rounded): every point
  // then maps inside the strip.
  if (!outline.contours.empty()) {
    double left = outline.contours.front().front().real(), right = left;
    for (const auto& c : outline.contours) {
      for (const Point x : c) {
        left = std::min(left, x.real());
        right = std::max(right, x.real());
        outline.top = std::min(outline.top, x.imag());
        outline.bottom = std::max(outline.bottom, x.imag());
      }
    }
    outline.left = left;
    outline.right = right;
  }
  return outline;
}

std::vector<std::vector<Point>> map_through_strip(const TextOutline& outline, const QuadStrip& strip, double padding) {
  std::vector<std::vector<Point>> mapped;
  const double width = outline.right - outline.left, height = outline.bottom - outline.top;
  if (!(width > 0.0) || !(height > 0.0)) return mapped;
  const double length = strip.quad_count();
  mapped.reserve(outline.contours.size());
  for (const auto& contour : outline.contours) {
    std::vector<Point> out;
    out.reserve(contour.size());
    for (const Point x : contour) {
      const double u = (x.real() - outline.left) / width * length;
      const double v = 1.0 - padding - (1.0 - 2.0 * padding) * (x.imag() - outline.top) / height;
      out.push_back(strip.at(u, v));
    }
    mapped.push_back(std::move(out));
  }
  return mapped;
}

}  // namespace pita::render
