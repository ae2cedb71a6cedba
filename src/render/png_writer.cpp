#include "render/png_writer.hpp"

#include <cstdint>
#include <cstring>
#include <new>
#include <vector>

#include <png.h>

#include "render/cairo_handles.hpp"

namespace pita::render {

namespace {

// libpng reports errors by longjmp to the setjmp of encode_rows; nothing is
// printed (the caller turns the status into pita's message).
[[noreturn]] void on_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void on_warning(png_structp, png_const_charp) {}

void append_data(png_structp png, png_bytep data, png_size_t length) {
  auto* bytes = static_cast<std::string*>(png_get_io_ptr(png));
  bool appended = true;
  try {
    bytes->append(reinterpret_cast<const char*>(data), length);
  } catch (const std::bad_alloc&) {
    appended = false;
  }
  // Outside the handler: png_error leaves by longjmp.
  if (!appended) png_error(png, "out of memory");
}

void flush_data(png_structp) {}

// One row of cairo pixels (native 32-bit words 0xAARRGGBB, colour
// premultiplied by alpha) as PNG bytes: RGBA un-premultiplied with rounding,
// (c * 255 + a / 2) / a, and all zero where a = 0, as cairo's PNG writer does;
// or RGB for a surface without alpha.
void convert_row(const unsigned char* in, int width, bool alpha, unsigned char* out) {
  for (int x = 0; x < width; ++x) {
    std::uint32_t pixel;
    std::memcpy(&pixel, in + 4 * static_cast<std::ptrdiff_t>(x), sizeof pixel);
    const std::uint32_t a = pixel >> 24, r = (pixel >> 16) & 0xFF, g = (pixel >> 8) & 0xFF, b = pixel & 0xFF;
    if (!alpha) {
      out[0] = static_cast<unsigned char>(r);
      out[1] = static_cast<unsigned char>(g);
      out[2] = static_cast<unsigned char>(b);
      out += 3;
      continue;
    }
    if (a == 0) {
      out[0] = out[1] = out[2] = out[3] = 0;
    } else {
      out[0] = static_cast<unsigned char>((r * 255 + a / 2) / a);
      out[1] = static_cast<unsigned char>((g * 255 + a / 2) / a);
      out[2] = static_cast<unsigned char>((b * 255 + a / 2) / a);
      out[3] = static_cast<unsigned char>(a);
    }
    out += 4;
  }
}

struct PixelRows {
  const unsigned char* data;
  int width, height, stride;
  bool alpha;
};

// Whether every pixel has alpha 255: cairo then writes an ARGB32 surface as
// RGB (its writer analyses the transparency), and so does pita, so that both
// files decode to the same format.
bool opaque(const PixelRows& image) {
  for (int y = 0; y < image.height; ++y) {
    const unsigned char* row = image.data + static_cast<std::ptrdiff_t>(y) * image.stride;
    for (int x = 0; x < image.width; ++x) {
      std::uint32_t pixel;
      std::memcpy(&pixel, row + 4 * static_cast<std::ptrdiff_t>(x), sizeof pixel);
      if ((pixel >> 24) != 0xFF) return false;
    }
  }
  return true;
}

// The libpng calls, between setjmp and its longjmp: no object with a
// destructor lives in this frame. `row` holds one converted row.
bool encode_rows(png_structp png, png_infop info, const PixelRows& image, const PngSettings& settings,
                 unsigned char* row) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               image.alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_color_16 white{};
  white.red = white.green = white.blue = white.gray = 0xFF;
  png_set_bKGD(png, info, &white);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, settings.filters);
  png_set_compression_level(png, settings.level);
  png_set_compression_strategy(png, settings.strategy);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    convert_row(image.data + static_cast<std::ptrdiff_t>(y) * image.stride, image.width, image.alpha, row);
    png_write_row(png, row);
  }
  png_write_end(png, info);
  return true;
}

}  // namespace

// Measured with bench/bench_png.cpp (`pita_bench --benchmark_filter=PngEncode`,
// docs/explanation/performance.md "PNG encoding"), CPU time per encoding and
// size, against cairo's writer (adaptive filtering, level 6): Fig. 1 24.1 ms
// and 64.2 kB; no filter at level 6 10.1 ms, 51.3 kB; level 4 8.8 ms, 52.3 kB;
// level 3 5.5 ms, 60.6 kB; level 1 5.0 ms, 62.3 kB; the RLE strategy 5.7 ms
// but 74.4 kB (226 kB for Fig. 23's picture). pita's figures are flat
// colours and thin lines, which row filters do not help. Level 4 without a
// filter is 2.7-3.4x faster than cairo's on Figs. 1, 23 and 25 and 9-18%
// smaller; level 3 is faster still but no smaller on a picture.
PngSettings default_png_settings() { return PngSettings{PNG_FILTER_NONE, 4, 0}; }

cairo_status_t write_png(cairo_surface_t* surface, std::string& bytes, const PngSettings& settings) {
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) return cairo_surface_status(surface);
  if (cairo_surface_get_type(surface) != CAIRO_SURFACE_TYPE_IMAGE) {
    return cairo_surface_write_to_png_stream(surface, append_to_string, &bytes);
  }
  const cairo_format_t format = cairo_image_surface_get_format(surface);
  if (format != CAIRO_FORMAT_ARGB32 && format != CAIRO_FORMAT_RGB24) {
    return cairo_surface_write_to_png_stream(surface, append_to_string, &bytes);
  }
  cairo_surface_flush(surface);
  PixelRows image{cairo_image_surface_get_data(surface), cairo_image_surface_get_width(surface),
                  cairo_image_surface_get_height(surface), cairo_image_surface_get_stride(surface),
                  format == CAIRO_FORMAT_ARGB32};
  if (image.width <= 0 || image.height <= 0 || image.data == nullptr) return CAIRO_STATUS_INVALID_SIZE;
  image.alpha = image.alpha && !opaque(image);
  std::vector<unsigned char> row;
  try {
    row.resize(static_cast<std::size_t>(image.width) * 4);
  } catch (const std::bad_alloc&) {
    return CAIRO_STATUS_NO_MEMORY;
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, on_error, on_warning);
  if (png == nullptr) return CAIRO_STATUS_NO_MEMORY;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return CAIRO_STATUS_NO_MEMORY;
  }
  png_set_write_fn(png, &bytes, append_data, flush_data);
  const std::size_t before = bytes.size();
  const bool ok = encode_rows(png, info, image, settings, row.data());
  png_destroy_write_struct(&png, &info);
  if (!ok) {
    bytes.resize(before);
    return CAIRO_STATUS_WRITE_ERROR;
  }
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace pita::render
