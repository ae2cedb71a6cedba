// The floor a pita process is compared with (docs/explanation/performance.md
// "Start-up"): a C++ program that links cairo and nothing of pita.
//   pita_cairo_floor --version                 print a line and exit: the cost of
//                                              starting a C++ program with cairo
//   pita_cairo_floor draw GEOMETRY OUT.svg     draw a figure's paths and texts,
//                                              read from GEOMETRY (written from pita's own
//                                              SVG of the figure by figure_geometry.py),
//                                              into an SVG file: the raw cairo program
//                                              drawing the same figure
// GEOMETRY: "W H" on the first line, then one item per line:
//   S r g b a width d...   a stroked path (SVG path data: M, L, C, Z, absolute)
//   F r g b a d...         a filled path
//   T size x y text...     a text, in cairo's toy font API ("Sans")
// Built a second time as pita_pango_floor (PITA_FLOOR_PANGO, linking
// pangocairo too), which lays the texts out with pango, as pita does.
#include <cairo-svg.h>
#include <cairo.h>
#ifdef PITA_FLOOR_PANGO
#include <pango/pangocairo.h>
#endif

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {

void trace(cairo_t* cr, std::istringstream& d) {
  std::string command;
  double x1 = 0, y1 = 0, x2 = 0, y2 = 0, x3 = 0, y3 = 0;
  while (d >> command) {
    if (command == "M") {
      d >> x1 >> y1;
      cairo_move_to(cr, x1, y1);
    } else if (command == "L") {
      d >> x1 >> y1;
      cairo_line_to(cr, x1, y1);
    } else if (command == "C") {
      d >> x1 >> y1 >> x2 >> y2 >> x3 >> y3;
      cairo_curve_to(cr, x1, y1, x2, y2, x3, y3);
    } else if (command == "Z") {
      cairo_close_path(cr);
    }
  }
}

int draw(const char* geometry, const char* out) {
  std::ifstream in(geometry);
  double width = 0, height = 0;
  if (!(in >> width >> height)) {
    std::cerr << "pita_cairo_floor: cannot read " << geometry << '\n';
    return 2;
  }
  cairo_surface_t* surface = cairo_svg_surface_create(out, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream item(line);
    std::string kind;
    item >> kind;
    if (kind == "T") {
      double size = 0, x = 0, y = 0;
      item >> size >> x >> y;
      std::string text;
      std::getline(item >> std::ws, text);
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      cairo_move_to(cr, x, y);
#ifdef PITA_FLOOR_PANGO
      PangoLayout* layout = pango_cairo_create_layout(cr);
      PangoFontDescription* font = pango_font_description_from_string("Sans");
      pango_font_description_set_absolute_size(font, size * PANGO_SCALE);
      pango_layout_set_font_description(layout, font);
      pango_font_description_free(font);
      pango_layout_set_text(layout, text.c_str(), static_cast<int>(text.size()));
      pango_cairo_show_layout(cr, layout);
      g_object_unref(layout);
#else
      cairo_select_font_face(cr, "Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
      cairo_set_font_size(cr, size);
      cairo_show_text(cr, text.c_str());
#endif
      continue;
    }
    double r = 0, g = 0, b = 0, a = 1, line_width = 1;
    item >> r >> g >> b >> a;
    if (kind == "S") item >> line_width;
    cairo_set_source_rgba(cr, r, g, b, a);
    trace(cr, item);
    if (kind == "S") {
      cairo_set_line_width(cr, line_width);
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      cairo_stroke(cr);
    } else {
      cairo_fill(cr);
    }
  }
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const bool ok = cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS;
  cairo_surface_destroy(surface);
  return ok ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "--version") {
    std::cout << "pita_cairo_floor (cairo " << cairo_version_string() << ")\n";
    return 0;
  }
  if (mode == "draw" && argc == 4) return draw(argv[2], argv[3]);
  std::cerr << "usage: pita_cairo_floor --version | draw GEOMETRY OUT.svg\n";
  return 2;
}
