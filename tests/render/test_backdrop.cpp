// The backdrop of raster animation frames (src/render/backdrop.cpp): painted
// over the backdrop, a figure has exactly the pixels of painting it whole,
// wherever the backdrop is used; where that cannot be promised it is not used.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <variant>

#include <cairo.h>
#include <gtest/gtest.h>

#include "render/backdrop.hpp"
#include "render/figure.hpp"
#include "render_support.hpp"
#include "scene/scene.hpp"

namespace pita::render::test {
namespace {

namespace fs = std::filesystem;

// The pixels of a surface, row by row (without the stride's padding).
std::string pixels(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  const int width = cairo_image_surface_get_width(surface), height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  std::string out;
  for (int y = 0; y < height; ++y) {
    out.append(reinterpret_cast<const char*>(data + static_cast<std::ptrdiff_t>(y) * stride),
               static_cast<std::size_t>(width) * 4);
  }
  return out;
}

std::string whole(const scene::Scene& s, const Figure& f, int width, int height, double scale) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  {
    ContextPtr cr(cairo_create(surface.get()));
    cairo_scale(cr.get(), scale, scale);
    paint_figure(cr.get(), s, f);
  }
  return pixels(surface.get());
}

int scaled(int side, double scale) { return static_cast<int>(std::round(side * scale)); }

// Every scene of scenes/ at three scales: the backdrop's pixels are the whole
// figure's, whether or not the backdrop is used; and it is used for some.
TEST(FrameBackdrop, PaintsThePixelsOfTheWholeFigure) {
  int used = 0, multi_panel_used = 0, checked = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    const scene::Scene s = scene::load_scene(entry.path());
    const Figure f = build_figure(s);
    if (leading_static_items(f) == std::vector<std::size_t>(f.drawings.size(), 0)) continue;
    for (const double scale : {0.5, 0.37}) {
      SCOPED_TRACE(entry.path().filename().string() + " at scale " + std::to_string(scale));
      const int width = scaled(s.canvas.width, scale), height = scaled(s.canvas.height, scale);
      const FrameBackdrop backdrop(s, f, width, height, scale);
      EXPECT_EQ(backdrop.active(), backdrop_is_exact(s, f, scale));
      used += backdrop.active();
      multi_panel_used += backdrop.active() && f.drawings.size() > 1;
      const SurfacePtr painted = backdrop.paint(f);
      EXPECT_TRUE(pixels(painted.get()) == whole(s, f, width, height, scale));
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
  EXPECT_GT(used, 10);
  EXPECT_GT(multi_panel_used, 0);
}

// Panels that touch a common pixel (no gap between cells, at a scale that
// puts their border inside a pixel) could paint it in another order: the
// backdrop is not used. With gaps between the cells, or one panel, it is.
TEST(FrameBackdrop, IsUsedOnlyWherePanelsShareNoPixel) {
  const scene::Scene s = eight_panels();
  Figure f = build_figure(s);
  EXPECT_TRUE(backdrop_is_exact(s, f, 1.0));
  Figure touching = f;
  touching.placements[1].cell.x = touching.placements[0].cell.x + touching.placements[0].cell.width - 0.5;
  EXPECT_FALSE(backdrop_is_exact(s, touching, 1.0));
  scene::Scene one = s;
  one.panels.resize(1);
  one.canvas.columns = 1;
  const Figure g = build_figure(one);
  EXPECT_TRUE(backdrop_is_exact(one, g, 0.37));
}

// The figure with every item but each panel's last one still: a backdrop of
// nearly everything.
Figure only_last_item_moving(Figure f) {
  for (Drawing& d : f.drawings) {
    for (Item& item : d.items) item.moving = false;
    if (!d.items.empty()) d.items.back().moving = true;
  }
  return f;
}

// A frame whose leading items move where the backdrop's did not (its layers
// differ) is painted whole, with the same pixels.
TEST(FrameBackdrop, AFrameThatDoesNotFitIsPaintedWhole) {
  const scene::Scene s = eight_panels();
  const Figure f = only_last_item_moving(build_figure(s));
  const int width = s.canvas.width, height = s.canvas.height;
  const FrameBackdrop backdrop(s, f, width, height, 1.0);
  Figure other = f;
  for (Drawing& d : other.drawings) {
    for (Item& item : d.items) item.moving = true;
  }
  EXPECT_TRUE(pixels(backdrop.paint(other).get()) == whole(s, other, width, height, 1.0));
}

// Items that do not move may still change between frames (a label placed
// around the moving data, a trail of "compare" frames): a frame whose leading
// items differ from the backdrop's in any way is painted whole.
TEST(FrameBackdrop, AFrameWhoseStaticItemsChangedIsPaintedWhole) {
  const scene::Scene s = eight_panels();
  const Figure f = only_last_item_moving(build_figure(s));
  const int width = s.canvas.width, height = s.canvas.height;
  const FrameBackdrop backdrop(s, f, width, height, 1.0);
  ASSERT_TRUE(backdrop.active());
  Figure other = f;
  int changed = 0;
  for (Drawing& d : other.drawings) {
    for (Item& item : d.items) {
      if (auto* line = std::get_if<Polyline>(&item.shape); line != nullptr && !line->points.empty() && !item.moving) {
        line->points.front() += Point(0.3, -0.2);
        ++changed;
        break;
      }
    }
  }
  ASSERT_GT(changed, 0);
  const std::string expected = whole(s, other, width, height, 1.0);
  EXPECT_FALSE(expected == whole(s, f, width, height, 1.0));  // the change shows
  EXPECT_TRUE(pixels(backdrop.paint(other).get()) == expected);
}

}  // namespace
}  // namespace pita::render::test
