// pita's PNG writer (src/render/png_writer.cpp) against cairo's own
// (cairo_surface_write_to_png, the independent reference): both files decode
// to the very same pixels, on every figure of scenes/ and on surfaces with
// every alpha; pita's files are no larger in all; errors are statuses.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

#include <cairo.h>
#include <gtest/gtest.h>
#include <png.h>

#include "render/cairo_handles.hpp"
#include "render/figure.hpp"
#include "render/png_writer.hpp"
#include "scene/scene.hpp"

namespace pita::render::test {
namespace {

namespace fs = std::filesystem;

struct Reader {
  std::string_view bytes;
  std::size_t at = 0;
};

cairo_status_t read_from(void* closure, unsigned char* data, unsigned int length) {
  auto* reader = static_cast<Reader*>(closure);
  if (reader->bytes.size() - reader->at < length) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(data, reader->bytes.data() + reader->at, length);
  reader->at += length;
  return CAIRO_STATUS_SUCCESS;
}

// The decoded pixels (cairo's reader), with the format and size in front.
std::string decoded(std::string_view png) {
  Reader reader{png};
  SurfacePtr surface(cairo_image_surface_create_from_png_stream(read_from, &reader));
  EXPECT_EQ(cairo_surface_status(surface.get()), CAIRO_STATUS_SUCCESS);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) return {};
  const int width = cairo_image_surface_get_width(surface.get()),
            height = cairo_image_surface_get_height(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  std::string out = std::to_string(cairo_image_surface_get_format(surface.get())) + " " + std::to_string(width) + "x" +
                    std::to_string(height) + ":";
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  for (int y = 0; y < height; ++y) {
    out.append(reinterpret_cast<const char*>(data + static_cast<std::ptrdiff_t>(y) * stride),
               static_cast<std::size_t>(width) * 4);
  }
  return out;
}

std::string by_cairo(cairo_surface_t* surface) {
  std::string bytes;
  EXPECT_EQ(cairo_surface_write_to_png_stream(surface, append_to_string, &bytes), CAIRO_STATUS_SUCCESS);
  return bytes;
}

std::string by_pita(cairo_surface_t* surface, const PngSettings& settings = default_png_settings()) {
  std::string bytes;
  EXPECT_EQ(write_png(surface, bytes, settings), CAIRO_STATUS_SUCCESS);
  return bytes;
}

TEST(PngWriter, EveryFigureDecodesToCairosPixelsInNoMoreBytes) {
  std::size_t ours = 0, theirs = 0;
  int figures = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PITA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const scene::Scene s = scene::load_scene(entry.path());
    const Figure f = build_figure(s);
    SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, s.canvas.width / 2, s.canvas.height / 2));
    {
      ContextPtr cr(cairo_create(surface.get()));
      cairo_scale(cr.get(), 0.5, 0.5);
      paint_figure(cr.get(), s, f);
    }
    const std::string reference = by_cairo(surface.get()), written = by_pita(surface.get());
    EXPECT_TRUE(decoded(written) == decoded(reference));
    ours += written.size();
    theirs += reference.size();
    ++figures;
  }
  EXPECT_GT(figures, 50);
  EXPECT_LE(ours, theirs);
}

// Every alpha from 0 to 255 over every colour step of 17, premultiplied as
// cairo keeps them: un-premultiplied as cairo does, by every setting.
TEST(PngWriter, EveryAlphaAndEverySettingGiveCairosPixels) {
  const int width = 256, height = 16;
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < height; ++y) {
    for (int a = 0; a < width; ++a) {
      const std::uint32_t c = static_cast<std::uint32_t>(y * 17);
      const std::uint32_t premultiplied = (c * static_cast<std::uint32_t>(a) + 127) / 255;
      const std::uint32_t pixel = (static_cast<std::uint32_t>(a) << 24) | (premultiplied << 16) |
                                  (((premultiplied * 3) / 4) << 8) | (premultiplied / 2);
      std::memcpy(data + static_cast<std::ptrdiff_t>(y) * stride + 4 * a, &pixel, 4);
    }
  }
  cairo_surface_mark_dirty(surface.get());
  const std::string reference = decoded(by_cairo(surface.get()));
  for (const PngSettings settings : {PngSettings{PNG_FILTER_NONE, 6}, PngSettings{PNG_ALL_FILTERS, 9},
                                     PngSettings{PNG_FILTER_PAETH, 1}, PngSettings{PNG_FILTER_NONE, 0}}) {
    EXPECT_TRUE(decoded(by_pita(surface.get(), settings)) == reference)
        << "filters " << settings.filters << ", level " << settings.level;
  }
}

// A surface without alpha is written as RGB, as cairo writes it.
TEST(PngWriter, AnOpaqueSurfaceIsWrittenAsRgb) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 40, 30));
  {
    ContextPtr cr(cairo_create(surface.get()));
    cairo_set_source_rgb(cr.get(), 0.2, 0.6, 0.9);
    cairo_paint(cr.get());
    cairo_set_source_rgb(cr.get(), 1, 0.5, 0);
    cairo_arc(cr.get(), 20, 15, 9.3, 0, 6.3);
    cairo_fill(cr.get());
  }
  const std::string written = by_pita(surface.get());
  ASSERT_GT(written.size(), 26u);
  EXPECT_EQ(static_cast<int>(static_cast<unsigned char>(written[25])), PNG_COLOR_TYPE_RGB);  // IHDR's colour type
  EXPECT_TRUE(decoded(written) == decoded(by_cairo(surface.get())));
}

// A surface in error gives its status and no byte; a surface that is not an
// image (a recording) is written by cairo's writer.
TEST(PngWriter, ErrorsAreStatusesAndOtherSurfacesGoToCairo) {
  SurfacePtr broken(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, -1, 5));
  std::string bytes;
  EXPECT_NE(write_png(broken.get(), bytes), CAIRO_STATUS_SUCCESS);
  EXPECT_TRUE(bytes.empty());
  const cairo_rectangle_t extents{0, 0, 10, 10};
  SurfacePtr recording(cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, &extents));
  EXPECT_EQ(write_png(recording.get(), bytes), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
}

}  // namespace
}  // namespace pita::render::test
