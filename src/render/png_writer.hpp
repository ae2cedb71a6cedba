// PNG files of cairo image surfaces (issue 38), written through libpng with
// the row filter and compression level chosen by measurement
// (docs/explanation/performance.md "PNG encoding"), instead of
// cairo_surface_write_to_png, which runs libpng's defaults: adaptive
// filtering of every row, the costliest part of every PNG pita writes.
//
// The pixels are cairo's: an ARGB32 surface is un-premultiplied into RGBA
// exactly as cairo's writer does it, or written as RGB when every pixel is
// opaque (as cairo does too), an RGB24 surface as RGB; 8 bits per channel,
// with cairo's white background chunk. A decoder reads the very pixels, in
// the same format, from either file; only the compressed stream differs.
#pragma once

#include <string>

#include <cairo.h>

namespace pita::render {

// How the rows are filtered and compressed (PNG filter flags, zlib level).
struct PngSettings {
  int filters = 0x08;  // PNG_FILTER_* flags of png.h: 0x08 is PNG_FILTER_NONE, 0xF8 PNG_ALL_FILTERS
  int level = 6;       // zlib compression level, 0 to 9
  int strategy = 0;    // zlib strategy (zlib.h): 0 Z_DEFAULT_STRATEGY, 1 Z_FILTERED, 3 Z_RLE
};

// The settings pita writes with (measured: png_writer.cpp).
PngSettings default_png_settings();

// Appends the PNG file of `surface` (flushed first) to `bytes`. Returns
// CAIRO_STATUS_SUCCESS, CAIRO_STATUS_NO_MEMORY, or CAIRO_STATUS_WRITE_ERROR
// when libpng fails; a surface that is not an ARGB32 or RGB24 image is
// written by cairo's own writer.
cairo_status_t write_png(cairo_surface_t* surface, std::string& bytes,
                         const PngSettings& settings = default_png_settings());

}  // namespace pita::render
