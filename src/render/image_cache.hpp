// The PNG images of "shapes", decoded by cairo once per thread and kept for
// the life of the thread (an animation paints the same image in every frame;
// each worker thread has its own copies, so that no cairo surface is shared
// between threads).
#pragma once

#include <cairo.h>

#include <string>

namespace pita::render {

// The decoded image at `path`, owned by the cache. Throws RenderError naming
// the file when cairo cannot read or decode it (a truncated or corrupt PNG).
cairo_surface_t* cached_image(const std::string& path, const std::string& name);

}  // namespace pita::render
