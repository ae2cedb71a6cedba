#include "render/pango_library.hpp"

#include <stdexcept>
#include <string>

#include <dlfcn.h>

namespace pita::render {

namespace {

// The run-time library of Debian's libpangocairo-1.0-0 (a Depends of the
// package, cmake/PitaInstall.cmake): its soname, stable since pango 1.0.
constexpr const char* kPangoCairoLibrary = "libpangocairo-1.0.so.0";

template <class Function>
void find_symbol(void* handle, const char* name, Function& function) {
  void* symbol = ::dlsym(handle, name);
  if (symbol == nullptr) {
    throw std::runtime_error(std::string(kPangoCairoLibrary) + " has no " + name +
                             ": install a pango of Debian 12 or later (libpangocairo-1.0-0)");
  }
  function = reinterpret_cast<Function>(symbol);
}

PangoLibrary load_pango() {
  // RTLD_LAZY: the functions pango and its libraries call are bound when
  // first called, rather than every function of theirs here.
  void* handle = ::dlopen(kPangoCairoLibrary, RTLD_LAZY | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* reason = ::dlerror();
    throw std::runtime_error(std::string("cannot load ") + kPangoCairoLibrary + " to lay out text (" +
                             (reason != nullptr ? reason : "unknown reason") +
                             "): install the Debian package libpangocairo-1.0-0");
  }
  // Never dlclose()d: pango's font map lives as long as the process.
  PangoLibrary library{};
  find_symbol(handle, "pango_cairo_create_layout", library.cairo_create_layout);
  find_symbol(handle, "pango_cairo_context_set_font_options", library.cairo_context_set_font_options);
  find_symbol(handle, "pango_cairo_show_layout", library.cairo_show_layout);
  find_symbol(handle, "pango_cairo_layout_path", library.cairo_layout_path);
  find_symbol(handle, "pango_layout_get_context", library.layout_get_context);
  find_symbol(handle, "pango_layout_context_changed", library.layout_context_changed);
  find_symbol(handle, "pango_layout_set_font_description", library.layout_set_font_description);
  find_symbol(handle, "pango_layout_set_text", library.layout_set_text);
  find_symbol(handle, "pango_layout_set_markup", library.layout_set_markup);
  find_symbol(handle, "pango_layout_get_pixel_size", library.layout_get_pixel_size);
  find_symbol(handle, "pango_layout_get_pixel_extents", library.layout_get_pixel_extents);
  find_symbol(handle, "pango_layout_get_extents", library.layout_get_extents);
  find_symbol(handle, "pango_font_description_from_string", library.font_description_from_string);
  find_symbol(handle, "pango_font_description_set_absolute_size", library.font_description_set_absolute_size);
  find_symbol(handle, "pango_font_description_free", library.font_description_free);
  find_symbol(handle, "pango_parse_markup", library.parse_markup);
  // GObject and GLib are dependencies of pangocairo: dlsym looks there too.
  find_symbol(handle, "g_object_unref", library.object_unref);
  find_symbol(handle, "g_base64_encode", library.base64_encode);
  find_symbol(handle, "g_free", library.free);
  return library;
}

}  // namespace

const PangoLibrary& pango() {
  static const PangoLibrary library = load_pango();
  return library;
}

}  // namespace pita::render
