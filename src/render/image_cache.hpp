// The PNG images of "shapes", decoded by cairo once per thread and kept
// while they fit (an animation paints the same image in every frame; each
// worker thread has its own copies, so that no cairo surface is shared
// between threads). The caches of all threads together hold at most
// kImageCacheBytes of decoded pixels, plus the one image each thread is
// painting: a thread evicts its least recently used images first.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include <cairo.h>

namespace pita::render {

// An image that cairo cannot read or decode (a truncated or corrupt PNG):
// what() is the reason, naming the image as the scene spells it.
class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr std::size_t kImageCacheBytes = std::size_t{256} << 20;

// The decoded image at `path`, owned by the cache: valid until this thread's
// next call (which may evict it). Throws ImageError: "corrupt PNG (...)",
// "not a PNG file (...)", or out of memory for a truly huge image.
// (check_images in render/figure.hpp decodes every image of a scene first and
// names the scene and the pointer.)
cairo_surface_t* cached_image(const std::string& path, const std::string& name);

// The decoded bytes the caches of all threads hold now.
std::size_t cached_image_bytes();

}  // namespace pita::render
