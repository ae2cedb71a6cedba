// Painting drawings with cairo (src/render/painter.cpp): shapes land where the
// view transform puts them, in their colours, clipped to their panel below
// its title; arrows get a head; texts and legends are placed as asked.
// Checked on the pixels of an image surface.
#include <cstdint>
#include <memory>

#include <cairo.h>
#include <gtest/gtest.h>

#include "render/painter.hpp"

namespace pita::render {
namespace {

constexpr std::uint32_t kRed = 0xFFFF0000u, kGreen = 0xFF00FF00u, kBlue = 0xFF0000FFu;
const Color kRedColor{1.0, 0.0, 0.0, 1.0}, kGreenColor{0.0, 1.0, 0.0, 1.0}, kBlueColor{0.0, 0.0, 1.0, 1.0};

// A transparent ARGB32 surface of width x height pixels.
class Surface {
 public:
  Surface(int width, int height)
      : surface_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height), cairo_surface_destroy),
        cr_(cairo_create(surface_.get()), cairo_destroy) {}
  cairo_t* cr() const { return cr_.get(); }
  // The premultiplied ARGB of the pixel whose top left corner is (x, y).
  std::uint32_t pixel(int x, int y) const {
    cairo_surface_flush(surface_.get());
    const unsigned char* row = cairo_image_surface_get_data(surface_.get()) +
                               static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(surface_.get());
    return reinterpret_cast<const std::uint32_t*>(row)[x];
  }
  std::uint32_t alpha(int x, int y) const { return pixel(x, y) >> 24; }
  // The rows of the topmost and lowest pixels with any ink, or -1.
  std::pair<int, int> ink_rows() const {
    const int width = cairo_image_surface_get_width(surface_.get());
    const int height = cairo_image_surface_get_height(surface_.get());
    int first = -1, last = -1;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        if (alpha(x, y) != 0) {
          if (first < 0) first = y;
          last = y;
          break;
        }
      }
    }
    return {first, last};
  }
  // The columns of the leftmost and rightmost pixels with any ink, or -1.
  std::pair<int, int> ink_columns() const {
    const int width = cairo_image_surface_get_width(surface_.get());
    const int height = cairo_image_surface_get_height(surface_.get());
    int first = -1, last = -1;
    for (int x = 0; x < width; ++x) {
      for (int y = 0; y < height; ++y) {
        if (alpha(x, y) != 0) {
          if (first < 0) first = x;
          last = x;
          break;
        }
      }
    }
    return {first, last};
  }

 private:
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_;
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr_;
};

// A panel filling the cell (x, y, width, height), 10 pixels per world unit,
// the world's origin at the cell's centre, y up.
PanelPlacement placement(double x, double y, double width, double height, double title = 0.0) {
  PanelPlacement p;
  p.cell = {x, y, width, height};
  p.title = {x, y, width, title};
  p.plot = p.cell;
  p.transform.world_center = {0.0, 0.0};
  p.transform.canvas_center = {x + 0.5 * width, y + 0.5 * height};
  p.transform.scale = 10.0;
  p.transform.y_up = true;
  return p;
}

Drawing with(Shape shape) {
  Drawing d;
  d.items.push_back({"/layers/0", -1, std::move(shape)});
  return d;
}

// The world square [-1, 1] x [1, 3] is the canvas square [40, 60] x [20, 40] (y up).
TEST(Painter, FilledPathsGoWhereTheViewPutsThem) {
  const Surface canvas(100, 100);
  const FilledPath square{{{{-1.0, 1.0}, {1.0, 1.0}, {1.0, 3.0}, {-1.0, 3.0}}}, kRedColor, 1.0, {}};
  paint_drawing(canvas.cr(), with(square), placement(0, 0, 100, 100), "Sans");
  EXPECT_EQ(canvas.pixel(50, 30), kRed);
  EXPECT_EQ(canvas.pixel(40, 20), kRed);
  EXPECT_EQ(canvas.pixel(59, 39), kRed);
  EXPECT_EQ(canvas.pixel(50, 70), 0u);  // where y down would have put it
  EXPECT_EQ(canvas.pixel(39, 30), 0u);
  EXPECT_EQ(canvas.pixel(50, 40), 0u);
}

TEST(Painter, ShapesAreClippedToTheirCellBelowTheTitle) {
  const Surface canvas(100, 100);
  const FilledPath everything{
      {{{-100.0, -100.0}, {100.0, -100.0}, {100.0, 100.0}, {-100.0, 100.0}}}, kGreenColor, 1.0, {}};
  paint_drawing(canvas.cr(), with(everything), placement(0, 0, 50, 100, 20.0), "Sans");
  EXPECT_EQ(canvas.pixel(25, 50), kGreen);
  EXPECT_EQ(canvas.pixel(25, 20), kGreen);
  EXPECT_EQ(canvas.pixel(25, 19), 0u);  // the title band
  EXPECT_EQ(canvas.pixel(50, 50), 0u);  // the next cell
}

// A circle of radius 2 world units is 20 pixels: filled inside, its outline
// 4 pixels wide from radius 18 to 22, empty beyond.
TEST(Painter, CirclesAreScaledByTheView) {
  const Surface canvas(100, 100);
  paint_drawing(canvas.cr(), with(Circle{{0.0, 0.0}, 2.0, LineStyle{kRedColor, 4.0, 1.0, {}}, kBlueColor}),
                placement(0, 0, 100, 100), "Sans");
  EXPECT_EQ(canvas.pixel(50, 50), kBlue);
  EXPECT_EQ(canvas.pixel(64, 50), kBlue);
  EXPECT_EQ(canvas.pixel(69, 50), kRed);
  EXPECT_EQ(canvas.pixel(50, 30), kRed);  // y up or down: the circle is symmetric
  EXPECT_EQ(canvas.pixel(74, 50), 0u);
}

// A line 4 pixels wide along y = 50 covers rows 48 to 51; dashes leave gaps.
TEST(Painter, PolylinesHaveTheirWidthAndDashes) {
  const Surface solid(100, 100);
  paint_drawing(solid.cr(), with(Polyline{{{-4.0, 0.0}, {4.0, 0.0}}, false, LineStyle{kGreenColor, 4.0, 1.0, {}}}),
                placement(0, 0, 100, 100), "Sans");
  for (int y = 48; y <= 51; ++y) EXPECT_EQ(solid.pixel(30, y), kGreen) << y;
  EXPECT_EQ(solid.pixel(30, 46), 0u);
  EXPECT_EQ(solid.pixel(30, 53), 0u);
  EXPECT_EQ(solid.pixel(95, 50), 0u);  // beyond the end cap
  const Surface dashed(100, 100);
  paint_drawing(dashed.cr(),
                with(Polyline{{{-4.0, 0.0}, {4.0, 0.0}}, false, LineStyle{kGreenColor, 2.0, 1.0, {10.0, 10.0}}}),
                placement(0, 0, 100, 100), "Sans");
  // Dashes from x = 10: on [10, 20] (and round caps 1 pixel beyond), off until 30.
  EXPECT_EQ(dashed.pixel(15, 50), kGreen);
  EXPECT_EQ(dashed.pixel(25, 50), 0u);
  EXPECT_EQ(dashed.pixel(35, 50), kGreen);
}

// From (-3, 0) to (3, 0) with a 1-pixel line: a body 1 pixel thick and a head
// kHeadMin = 8 pixels long ending at x = 80, 3.2 pixels to each side at its base.
TEST(Painter, ArrowsEndInAHeadAtTheirTip) {
  const Surface canvas(100, 100);
  paint_drawing(canvas.cr(), with(ArrowShape{{-3.0, 0.0}, {3.0, 0.0}, LineStyle{kRedColor, 1.0, 1.0, {}}}),
                placement(0, 0, 100, 100), "Sans");
  EXPECT_EQ(canvas.pixel(74, 51), kRed);  // inside the head, off the body
  EXPECT_EQ(canvas.pixel(74, 48), kRed);
  EXPECT_EQ(canvas.pixel(60, 51), 0u);  // beside the body
  // The body from y = 49.5 to 50.5 covers half of rows 49 and 50.
  EXPECT_GT(canvas.alpha(40, 50), 64u);
  EXPECT_LT(canvas.alpha(40, 50), 192u);
  EXPECT_GT(canvas.alpha(40, 49), 64u);
  EXPECT_EQ(canvas.pixel(82, 50), 0u);  // beyond the tip
  EXPECT_EQ(canvas.pixel(76, 47), 0u);  // beside the head, which narrows to its tip
}

TEST(Painter, TextIsAlignedOnItsX) {
  const auto ink = [](TextAlign align) {
    const Surface canvas(300, 60);
    paint_text(canvas.cr(), "Hello", "Sans", 20.0, kBlueColor, 150.0, 10.0, align);
    return canvas.ink_columns();
  };
  const auto [left_first, left_last] = ink(TextAlign::left);
  EXPECT_GE(left_first, 149);
  EXPECT_GT(left_last, 160);
  const auto [center_first, center_last] = ink(TextAlign::center);
  EXPECT_LT(center_first, 145);
  EXPECT_GT(center_last, 155);
  const auto [right_first, right_last] = ink(TextAlign::right);
  EXPECT_LT(right_first, 140);
  EXPECT_LE(right_last, 151);
  // The same text, moved: centred text spans about as far on each side.
  EXPECT_NEAR((center_first + center_last) / 2.0, 150.0, 4.0);
}

// The box text_ink_box measures (what `pita lint` checks) holds the ink
// paint_text leaves, within a pixel of antialiasing, for each alignment,
// with markup and on two lines.
TEST(Painter, TextInkBoxHoldsThePaintedInk) {
  struct Case {
    std::string text;
    TextAlign align;
    bool markup;
  };
  for (const Case& c : {Case{"Hello", TextAlign::left, false}, Case{"gjpq Ay", TextAlign::center, false},
                        Case{"F<sub>A</sub>", TextAlign::right, true}, Case{"two\nlines", TextAlign::left, false}}) {
    const Surface canvas(300, 120);
    paint_text(canvas.cr(), c.text, "Sans", 20.0, kBlueColor, 150.0, 20.0, c.align, c.markup);
    const auto [x0, x1] = canvas.ink_columns();
    const auto [y0, y1] = canvas.ink_rows();
    const Rect box = text_ink_box(c.text, "Sans", 20.0, {150.0, 20.0, c.align}, c.markup);
    EXPECT_NEAR(box.x, x0, 1.5) << c.text;
    EXPECT_NEAR(box.x + box.width, x1 + 1, 1.5) << c.text;
    EXPECT_NEAR(box.y, y0, 1.5) << c.text;
    EXPECT_NEAR(box.y + box.height, y1 + 1, 1.5) << c.text;
  }
}

// Labels: markup only when the text has a tag and parses; "F<sub>A</sub>"
// drawn as markup is narrower than its 14 characters drawn as written, and
// its subscript reaches lower than the F.
TEST(Painter, LabelsTakeMarkupOnlyWhenItParses) {
  EXPECT_TRUE(is_markup("F<sub>A</sub>"));
  EXPECT_FALSE(is_markup("F_A"));
  EXPECT_FALSE(is_markup("a < b"));
  EXPECT_FALSE(is_markup("F<sub>A"));
  EXPECT_FALSE(is_markup("x <= 1 & y"));
  const auto ink = [](bool markup) {
    const Surface canvas(400, 60);
    paint_text(canvas.cr(), "F<sub>A</sub>", "Sans", 20.0, kBlueColor, 10.0, 10.0, TextAlign::left, markup);
    return canvas.ink_columns();
  };
  const auto [markup_first, markup_last] = ink(true);
  const auto [plain_first, plain_last] = ink(false);
  EXPECT_LT(markup_last - markup_first, 45);  // "F" and a small "A"
  EXPECT_GT(plain_last - plain_first, 100);   // fourteen characters
  // Drawn through a Label, the same text is markup.
  const Surface canvas(400, 60);
  paint_drawing(canvas.cr(), with(Label{"F<sub>A</sub>", {-10.0, 0.0}, 20.0, kBlueColor}),
                placement(0.0, 0.0, 400.0, 60.0), "Sans");
  const auto [label_first, label_last] = canvas.ink_columns();
  EXPECT_LT(label_last - label_first, 45);
}

// A top-right legend of size 11 in a 200 x 100 cell: 121 pixels wide, 6 from
// the edges, its first swatch a 2-pixel line along y = 14.25 from x = 73 to 95.
TEST(Painter, LegendSitsInItsCorner) {
  const auto paint = [](scene::LegendLayer::Corner corner) {
    auto canvas = std::make_unique<Surface>(200, 100);
    Drawing d;
    d.legends.push_back(Legend{corner, 11.0, {{kRedColor, "P6"}}});
    paint_drawing(canvas->cr(), d, placement(0, 0, 200, 100), "Sans");
    return canvas;
  };
  const auto right = paint(scene::LegendLayer::Corner::top_right);
  EXPECT_EQ(right->pixel(80, 14), kRed);
  EXPECT_EQ(right->pixel(15, 14), 0u);
  const auto left = paint(scene::LegendLayer::Corner::top_left);
  EXPECT_EQ(left->pixel(15, 14), kRed);
  EXPECT_EQ(left->pixel(80, 14), 0u);
  // Bottom left: the line at y = 100 - 6 - 16.5 + 8.25 = 85.75.
  const auto bottom = paint(scene::LegendLayer::Corner::bottom_left);
  EXPECT_EQ(bottom->pixel(15, 85), kRed);
  EXPECT_EQ(bottom->pixel(15, 14), 0u);
}

}  // namespace
}  // namespace pita::render
