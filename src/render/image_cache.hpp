// The PNG images of "shapes", decoded by cairo once per thread and kept for
// the life of the thread (an animation paints the same image in every frame;
// each worker thread has its own copies, so that no cairo surface is shared
// between threads).
#pragma once

#include <cairo.h>

#include <stdexcept>
#include <string>

namespace pita::render {

// An image that cairo cannot read or decode (a truncated or corrupt PNG):
// what() is the reason, naming the image as the scene spells it.
class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The decoded image at `path`, owned by the cache. Throws ImageError.
// (check_images in render/figure.hpp decodes every image of a scene first and
// names the scene and the pointer.)
cairo_surface_t* cached_image(const std::string& path, const std::string& name);

}  // namespace pita::render
