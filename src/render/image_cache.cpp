#include "render/image_cache.hpp"

#include <map>
#include <memory>

#include <fmt/format.h>

#include "render/cairo_handles.hpp"

namespace pita::render {

cairo_surface_t* cached_image(const std::string& path, const std::string& name) {
  thread_local std::map<std::string, SurfacePtr> cache;
  auto it = cache.find(path);
  if (it == cache.end()) {
    SurfacePtr surface(cairo_image_surface_create_from_png(path.c_str()));
    const cairo_status_t status = cairo_surface_status(surface.get());
    if (status != CAIRO_STATUS_SUCCESS) {
      throw ImageError(fmt::format("cannot read the image \"{}\": {}", name,
                                              status == CAIRO_STATUS_READ_ERROR ? "not a valid PNG (truncated or corrupt)"
                                                                                : cairo_status_to_string(status)));
    }
    it = cache.emplace(path, std::move(surface)).first;
  }
  return it->second.get();
}

}  // namespace pita::render
