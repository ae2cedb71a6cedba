// PNG comparison (golden/image_compare.hpp) on images drawn here with cairo.
#include <cstring>
#include <string>

#include <cairo.h>
#include <gtest/gtest.h>

#include "golden/image_compare.hpp"

namespace pita::golden {
namespace {

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// A 40x30 white image with a black 10x10 square at (x, y); optionally one
// pixel at (0, 0) set to grey level `corner`.
std::string png(int x, int y, int corner = 255, int width = 40) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, 30);
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_rectangle(cr, x, y, 10, 10);  // integer-aligned: no antialiasing
  cairo_fill(cr);
  cairo_set_source_rgb(cr, corner / 255.0, corner / 255.0, corner / 255.0);
  cairo_rectangle(cr, 0, 0, 1, 1);
  cairo_fill(cr);
  cairo_destroy(cr);
  std::string bytes;
  cairo_surface_write_to_png_stream(s, append, &bytes);
  cairo_surface_destroy(s);
  return bytes;
}

TEST(ImageCompare, IdenticalImagesMatch) {
  const ImageComparison c = compare_png(png(5, 5), png(5, 5), {0, 0.0});
  EXPECT_TRUE(c.matches);
  EXPECT_TRUE(c.same_size);
  EXPECT_EQ(c.differing, 0u);
  EXPECT_EQ(c.max_channel_difference, 0);
}

TEST(ImageCompare, ChannelToleranceAbsorbsSmallChanges) {
  EXPECT_TRUE(compare_png(png(5, 5), png(5, 5, 254), {2, 0.0}).matches);
  const ImageComparison strict = compare_png(png(5, 5), png(5, 5, 254), {0, 0.0});
  EXPECT_FALSE(strict.matches);
  EXPECT_EQ(strict.differing, 1u);
  EXPECT_EQ(strict.max_channel_difference, 1);
}

TEST(ImageCompare, MovedSquareDiffersByExactlyItsSymmetricDifference) {
  // Squares [5, 15) and [8, 18) along x, same rows: 3 columns leave, 3 arrive.
  const ImageComparison c = compare_png(png(5, 5), png(8, 5), {2, 0.0});
  EXPECT_FALSE(c.matches);
  EXPECT_EQ(c.differing, 2u * 3u * 10u);
  EXPECT_NEAR(c.share, 60.0 / (40.0 * 30.0), 1e-15);
  // ... unless that share is allowed.
  EXPECT_TRUE(compare_png(png(5, 5), png(8, 5), {2, 0.05}).matches);
}

TEST(ImageCompare, DiffImageIsRedExactlyWhereImagesDiffer) {
  const ImageComparison c = compare_png(png(5, 5), png(8, 5), {2, 0.0});
  const ImageComparison reread = compare_png(c.diff_png, c.diff_png, {0, 0.0});  // decodes
  EXPECT_TRUE(reread.matches);
  // Decode the diff and count saturated red pixels.
  struct Reader {
    const std::string* bytes;
    std::size_t at;
  } reader{&c.diff_png, 0};
  cairo_surface_t* s = cairo_image_surface_create_from_png_stream(
      [](void* closure, unsigned char* data, unsigned int length) {
        auto* r = static_cast<Reader*>(closure);
        if (r->bytes->size() - r->at < length) return CAIRO_STATUS_READ_ERROR;
        std::memcpy(data, r->bytes->data() + r->at, length);
        r->at += length;
        return CAIRO_STATUS_SUCCESS;
      },
      &reader);
  ASSERT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  int red = 0;
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) {
      std::uint32_t p;
      std::memcpy(&p, data + y * stride + 4 * x, 4);
      const bool is_red = (p & 0x00FFFFFFu) == 0x00FF0000u;
      const bool moved = y >= 5 && y < 15 && ((x >= 5 && x < 8) || (x >= 15 && x < 18));
      EXPECT_EQ(is_red, moved) << x << "," << y;
      red += is_red;
    }
  }
  EXPECT_EQ(red, 60);
  cairo_surface_destroy(s);
}

TEST(ImageCompare, DifferentSizesNeverMatch) {
  const ImageComparison c = compare_png(png(5, 5), png(5, 5, 255, 41), {255, 1.0});
  EXPECT_FALSE(c.matches);
  EXPECT_FALSE(c.same_size);
  EXPECT_EQ(c.actual_width, 41);
  EXPECT_FALSE(c.diff_png.empty());
}

TEST(ImageCompare, CorruptedPngsAreNamedErrors) {
  const std::string good = png(5, 5);
  for (const std::string& bad : {std::string(), std::string("garbage"), good.substr(0, good.size() / 2)}) {
    try {
      compare_png(bad, good, {});
      FAIL() << "expected a GoldenError";
    } catch (const GoldenError& e) {
      EXPECT_NE(std::string(e.what()).find("expected"), std::string::npos) << e.what();
    }
    try {
      compare_png(good, bad, {});
      FAIL() << "expected a GoldenError";
    } catch (const GoldenError& e) {
      EXPECT_NE(std::string(e.what()).find("actual"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace pita::golden
