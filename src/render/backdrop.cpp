#include "render/backdrop.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <cairo.h>
#include <fmt/format.h>

#include "render/layout.hpp"
#include "render/painter.hpp"
#include "render/panel_drawing.hpp"

namespace pita::render {

namespace {

// A rectangle in device pixels at `scale`.
Rect scaled(const Rect& r, double scale) { return {r.x * scale, r.y * scale, r.width * scale, r.height * scale}; }

// The whole pixels a clip rectangle lets paint: those it covers even partly.
Rect pixels_touched(const Rect& r) {
  const double x0 = std::floor(r.x), y0 = std::floor(r.y);
  return {x0, y0, std::ceil(r.x + r.width) - x0, std::ceil(r.y + r.height) - y0};
}

bool overlap(const Rect& a, const Rect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// The box of a title's ink grown by `by` pixels: antialiasing touches the
// pixels around it (and the box is measured unscaled).
Rect grown(const Rect& r, double by) { return {r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by}; }

SurfacePtr new_surface(const scene::Scene& scene, int width, int height) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw RenderError(scene.path, "",
                      fmt::format("cairo failed: {}", cairo_status_to_string(cairo_surface_status(surface.get()))));
  }
  return surface;
}

void paint_on(const scene::Scene& scene, cairo_surface_t* surface, double scale, const Figure& figure,
              const FigurePart& part) {
  {
    ContextPtr cr(cairo_create(surface));
    cairo_scale(cr.get(), scale, scale);
    paint_figure(cr.get(), scene, figure, part);
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) {
      throw RenderError(scene.path, "",
                        fmt::format("cairo failed: {}", cairo_status_to_string(cairo_status(cr.get()))));
    }
  }
  cairo_surface_flush(surface);
}

}  // namespace

std::vector<std::size_t> leading_static_items(const Figure& figure) {
  std::vector<std::size_t> leading;
  for (const Drawing& drawing : figure.drawings) {
    const auto first_moving =
        std::find_if(drawing.items.begin(), drawing.items.end(), [](const Item& item) { return item.moving; });
    leading.push_back(static_cast<std::size_t>(first_moving - drawing.items.begin()));
  }
  return leading;
}

bool backdrop_is_exact(const scene::Scene& scene, const Figure& figure, double scale) {
  const std::size_t n = figure.placements.size();
  if (n != figure.drawings.size() || n != scene.panels.size()) return false;
  if (n <= 1) return true;
  std::vector<Rect> areas;
  for (const PanelPlacement& place : figure.placements) {
    areas.push_back(pixels_touched(scaled(drawing_area(place), scale)));
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (overlap(areas[i], areas[j])) return false;
    }
    const std::string& title = scene.panels[i].title;
    if (title.empty()) continue;
    const Rect ink = grown(scaled(text_ink_box(title, scene.canvas.font, kPanelTitleSize,
                                               panel_title_placement(figure.placements[i]), is_markup(title)),
                                  scale),
                           2.0);
    for (std::size_t j = 0; j < n; ++j) {
      if (j != i && overlap(ink, areas[j])) return false;
    }
  }
  return true;
}

FrameBackdrop::FrameBackdrop(const scene::Scene& scene, const Figure& first, int width, int height, double scale)
    : scene_(scene), width_(width), height_(height), scale_(scale), leading_(leading_static_items(first)) {
  const bool shares_something = std::any_of(leading_.begin(), leading_.end(), [](std::size_t k) { return k > 0; });
  if (!shares_something || !backdrop_is_exact(scene, first, scale)) return;
  for (std::size_t i = 0; i < leading_.size(); ++i) {
    const std::vector<Item>& items = first.drawings[i].items;
    leading_items_.emplace_back(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(leading_[i]));
  }
  surface_ = new_surface(scene, width, height);
  paint_on(scene, surface_.get(), scale, first, BackdropPart{&leading_});
}

SurfacePtr FrameBackdrop::paint(const Figure& frame) const {
  SurfacePtr surface = new_surface(scene_, width_, height_);
  bool over = active() && frame.drawings.size() == leading_.size();
  for (std::size_t i = 0; over && i < leading_.size(); ++i) {
    const std::vector<Item>& items = frame.drawings[i].items;
    over = items.size() >= leading_[i] && std::equal(leading_items_[i].begin(), leading_items_[i].end(), items.begin());
  }
  if (!over) {
    paint_on(scene_, surface.get(), scale_, frame, WholeFigure{});
    return surface;
  }
  // The backdrop's pixels (same size and format, so the same stride).
  cairo_surface_flush(surface.get());
  const int stride = cairo_image_surface_get_stride(surface_.get());
  std::memcpy(cairo_image_surface_get_data(surface.get()), cairo_image_surface_get_data(surface_.get()),
              static_cast<std::size_t>(stride) * static_cast<std::size_t>(height_));
  cairo_surface_mark_dirty(surface.get());
  paint_on(scene_, surface.get(), scale_, frame, RestPart{&leading_});
  return surface;
}

}  // namespace pita::render
