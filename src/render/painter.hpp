// Paints drawings, titles and legends on a cairo context whose user units are
// canvas pixels.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <cairo.h>

#include "render/drawing.hpp"
#include "render/layout.hpp"

namespace pita::render {

// Arrowheads: length in pixels, max(kHeadMin, kHeadPerWidth * line width).
inline constexpr double kHeadMin = 8.0;
inline constexpr double kHeadPerWidth = 4.0;

// Which of a drawing's items paint_drawing paints: items [from, to) and,
// with `legends`, the legends (all of them by default). An animation's
// backdrop paints each panel's leading items once and every frame the rest
// (render/backdrop.hpp).
struct ItemRange {
  std::size_t from = 0;
  std::size_t to = static_cast<std::size_t>(-1);
  bool legends = true;
};

void paint_drawing(cairo_t* cr, const Drawing& drawing, const PanelPlacement& placement, const std::string& font,
                   const ItemRange& range = {});

// Pixel coordinates of the image's file -> canvas pixels under `view`.
Affine2 image_to_canvas(const Image& image, const ViewTransform& view);

enum class TextAlign { left, center, right };
// Draws `text` with its box's top at y, aligned on x; with `markup`, the text
// is Pango markup ("F<sub>A</sub>"), else it is drawn as written.
void paint_text(cairo_t* cr, const std::string& text, const std::string& font, double size, const Color& color,
                double x, double y, TextAlign align, bool markup = false);

// Where paint_text draws: the top-left corner of the text's layout is
// (x, y) moved left by its width (right) or half of it (center).
struct TextPlacement {
  double x = 0.0, y = 0.0;
  TextAlign align = TextAlign::left;
};

// The box of the ink `text` leaves when paint_text draws it at `at`, in the
// same units (canvas pixels): what `pita lint` checks (src/lint/).
Rect text_ink_box(const std::string& text, const std::string& font, double size, const TextPlacement& at, bool markup);

// Where each text of a figure is drawn, so that the painter and the lint
// agree: a label at its world point, the scene's title, a panel's title.
TextPlacement label_placement(const Label& label, const ViewTransform& view);
TextPlacement scene_title_placement(const scene::Canvas& canvas);
TextPlacement panel_title_placement(const PanelPlacement& placement);

// The area a panel's drawing and legends are painted in (and clipped to):
// its cell below its title band.
Rect drawing_area(const PanelPlacement& placement);

// A legend in its corner of `area`: its box (the swatches' legends; the
// text-only ones are their lines' boxes) and per entry its swatch (a
// segment, absent without swatches) and where its text goes.
struct LegendRow {
  const LegendEntry* entry = nullptr;
  Point swatch_from, swatch_to;
  TextPlacement text;
  Color text_color;
};
struct LegendGeometry {
  Rect box;
  std::vector<LegendRow> rows;
};
LegendGeometry legend_geometry(const Legend& legend, const Rect& area);

// Whether a label's text is drawn as Pango markup: it has a '<' and parses as
// markup. Any other text (no tag, or "a < b") is drawn as written, so plain
// labels are unchanged (docs/reference/render.md, the "label" field).
bool is_markup(const std::string& text);

}  // namespace pita::render
