// pango (and GLib with it), loaded when first needed rather than when pita
// starts: the first text laid out, or the first animated SVG.
//
// Linking pangocairo made every process map pango, glib, gobject, harfbuzz,
// fribidi and their kin (17 more shared libraries and their relocations)
// before main(), also `pita eval` and figures without a word of text: about
// half of what a one-figure process spent starting (docs/explanation/
// performance.md "Start-up"). Now pita links cairo only, and the functions of
// pango it uses are looked up in libpangocairo with dlopen/dlsym on first use.
// The types still come from pango's headers at compile time.
#pragma once

#include <pango/pangocairo.h>

namespace pita::render {

// The pango, GObject and GLib functions pita calls, by their C names (GLib's
// come with pango, which depends on it; the animated SVG uses them too).
struct PangoLibrary {
  decltype(&::pango_cairo_create_layout) cairo_create_layout;
  decltype(&::pango_cairo_context_set_font_options) cairo_context_set_font_options;
  decltype(&::pango_cairo_show_layout) cairo_show_layout;
  decltype(&::pango_cairo_layout_path) cairo_layout_path;
  decltype(&::pango_layout_get_context) layout_get_context;
  decltype(&::pango_layout_context_changed) layout_context_changed;
  decltype(&::pango_layout_set_font_description) layout_set_font_description;
  decltype(&::pango_layout_set_text) layout_set_text;
  decltype(&::pango_layout_set_markup) layout_set_markup;
  decltype(&::pango_layout_get_pixel_size) layout_get_pixel_size;
  decltype(&::pango_layout_get_pixel_extents) layout_get_pixel_extents;
  decltype(&::pango_layout_get_extents) layout_get_extents;
  decltype(&::pango_font_description_from_string) font_description_from_string;
  decltype(&::pango_font_description_set_absolute_size) font_description_set_absolute_size;
  decltype(&::pango_font_description_free) font_description_free;
  decltype(&::pango_parse_markup) parse_markup;
  decltype(&::g_object_unref) object_unref;
  decltype(&::g_base64_encode) base64_encode;
  decltype(&::g_free) free;
};

// The library, loaded on the first call (thread-safe) and kept for the life
// of the process. Throws std::runtime_error naming the library and the
// Debian package to install when it cannot be loaded or lacks a function.
const PangoLibrary& pango();

}  // namespace pita::render
