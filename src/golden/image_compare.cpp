#include "golden/image_compare.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>

#include <cairo.h>
#include <fmt/format.h>

#include "render/cairo_handles.hpp"
#include "render/png_writer.hpp"

namespace pita::golden {

namespace {

using Surface = render::SurfacePtr;

struct Reader {
  std::string_view bytes;
  std::size_t at = 0;
};

cairo_status_t read_chunk(void* closure, unsigned char* data, unsigned int length) {
  Reader* r = static_cast<Reader*>(closure);
  if (r->bytes.size() - r->at < length) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(data, r->bytes.data() + r->at, length);
  r->at += length;
  return CAIRO_STATUS_SUCCESS;
}

std::uint32_t big_endian(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

struct PngSize {
  std::uint32_t width = 0, height = 0;
};

// The size a PNG declares in its IHDR chunk (PNG spec 11.2.2: the signature,
// then the first chunk's length, "IHDR", width and height, big-endian), read
// before anything is decoded: a few bytes can declare billions of pixels.
PngSize declared_size(std::string_view png, const char* which) {
  if (png.size() < 24 || std::memcmp(png.data(), "\x89PNG\r\n\x1a\n", 8) != 0 ||
      std::memcmp(png.data() + 12, "IHDR", 4) != 0) {
    throw GoldenError(std::string("the ") + which + " image is not a PNG file");
  }
  const PngSize size{big_endian(png, 16), big_endian(png, 20)};
  if (size.width == 0 || size.height == 0 || size.width > kMaxImageSide || size.height > kMaxImageSide) {
    throw GoldenError(
        fmt::format("the {} PNG declares {}x{} pixels; images are compared up to "
                    "{}x{} (not decoded)",
                    which, size.width, size.height, kMaxImageSide, kMaxImageSide));
  }
  return size;
}

// Decodes a PNG into an ARGB32 image surface.
Surface decode(std::string_view png, const char* which) {
  declared_size(png, which);
  Reader reader{png};
  Surface decoded(cairo_image_surface_create_from_png_stream(read_chunk, &reader));
  if (cairo_surface_status(decoded.get()) != CAIRO_STATUS_SUCCESS) {
    throw GoldenError(std::string("the ") + which + " PNG cannot be decoded (" +
                      cairo_status_to_string(cairo_surface_status(decoded.get())) + "; truncated or corrupted?)");
  }
  // Grey or palette PNGs decode to other formats: paint into ARGB32.
  const int w = cairo_image_surface_get_width(decoded.get());
  const int h = cairo_image_surface_get_height(decoded.get());
  Surface argb(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
  cairo_t* cr = cairo_create(argb.get());
  cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
  cairo_set_source_surface(cr, decoded.get(), 0, 0);
  cairo_paint(cr);
  cairo_destroy(cr);
  cairo_surface_flush(argb.get());
  return argb;
}

std::uint32_t pixel(cairo_surface_t* s, int x, int y) {
  const unsigned char* row = cairo_image_surface_get_data(s) + y * cairo_image_surface_get_stride(s);
  std::uint32_t p;
  std::memcpy(&p, row + 4 * x, 4);
  return p;
}

void set_pixel(cairo_surface_t* s, int x, int y, std::uint32_t p) {
  unsigned char* row = cairo_image_surface_get_data(s) + y * cairo_image_surface_get_stride(s);
  std::memcpy(row + 4 * x, &p, 4);
}

int channel_difference(std::uint32_t a, std::uint32_t b) {
  int worst = 0;
  for (int shift = 0; shift < 32; shift += 8) {
    const int ca = static_cast<int>((a >> shift) & 0xFF), cb = static_cast<int>((b >> shift) & 0xFF);
    worst = std::max(worst, ca > cb ? ca - cb : cb - ca);
  }
  return worst;
}

// Light grey of the same brightness family: 0xFF A, each channel 3/4 of the way to white.
std::uint32_t faded(std::uint32_t p) {
  const auto alpha = (p >> 24) & 0xFF;
  const auto r = (p >> 16) & 0xFF, g = (p >> 8) & 0xFF, b = p & 0xFF;
  // Un-premultiply against white for display, then fade.
  const auto grey = (r + g + b) / 3 + (255 - alpha);
  const auto v = 191 + std::min<std::uint32_t>(grey, 255) / 4;
  return 0xFF000000u | (v << 16) | (v << 8) | v;
}

std::string encode(cairo_surface_t* s) {
  std::string bytes;
  cairo_surface_mark_dirty(s);
  render::write_png(s, bytes);
  return bytes;
}

constexpr std::uint32_t kRed = 0xFFFF0000u;

}  // namespace

ImageComparison compare_png(std::string_view expected_png, std::string_view actual_png,
                            const ImageTolerance& tolerance) {
  // Sizes first, from the headers: the expected image is decoded only when
  // it has the actual image's size.
  const PngSize declared = declared_size(expected_png, "expected");
  const Surface actual = decode(actual_png, "actual");
  ImageComparison c;
  c.expected_width = static_cast<int>(declared.width);
  c.expected_height = static_cast<int>(declared.height);
  c.actual_width = cairo_image_surface_get_width(actual.get());
  c.actual_height = cairo_image_surface_get_height(actual.get());
  c.same_size = c.expected_width == c.actual_width && c.expected_height == c.actual_height;

  if (!c.same_size) {
    c.differing = static_cast<std::size_t>(c.actual_width) * static_cast<std::size_t>(c.actual_height);
    c.share = 1.0;
    c.max_channel_difference = 255;
    // The actual image inside a red border.
    const int border = 4;
    Surface diff(
        cairo_image_surface_create(CAIRO_FORMAT_ARGB32, c.actual_width + 2 * border, c.actual_height + 2 * border));
    cairo_t* cr = cairo_create(diff.get());
    cairo_set_source_rgb(cr, 1, 0, 0);
    cairo_paint(cr);
    cairo_set_source_surface(cr, actual.get(), border, border);
    cairo_paint(cr);
    cairo_destroy(cr);
    c.diff_png = encode(diff.get());
    return c;
  }

  const Surface expected = decode(expected_png, "expected");
  if (cairo_image_surface_get_width(expected.get()) != c.expected_width ||
      cairo_image_surface_get_height(expected.get()) != c.expected_height) {
    throw GoldenError("the expected PNG decodes to another size than its header declares");
  }
  const int w = c.expected_width, h = c.expected_height;
  Surface diff(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
  cairo_surface_flush(diff.get());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::uint32_t e = pixel(expected.get(), x, y), a = pixel(actual.get(), x, y);
      const int d = channel_difference(e, a);
      c.max_channel_difference = std::max(c.max_channel_difference, d);
      const bool differs = d > tolerance.channel;
      if (differs) ++c.differing;
      set_pixel(diff.get(), x, y, differs ? kRed : faded(e));
    }
  }
  const double pixels = static_cast<double>(w) * static_cast<double>(h);
  c.share = pixels > 0.0 ? static_cast<double>(c.differing) / pixels : 0.0;
  c.matches = c.share <= tolerance.max_share;
  c.diff_png = encode(diff.get());
  return c;
}

}  // namespace pita::golden
