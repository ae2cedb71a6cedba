// Paints drawings, titles and legends on a cairo context whose user units are
// canvas pixels.
#pragma once

#include <cairo.h>

#include <string>

#include "render/drawing.hpp"
#include "render/layout.hpp"

namespace pita::render {

// Arrowheads: length in pixels, max(kHeadMin, kHeadPerWidth * line width).
inline constexpr double kHeadMin = 8.0;
inline constexpr double kHeadPerWidth = 4.0;

void paint_drawing(cairo_t* cr, const Drawing& drawing, const PanelPlacement& placement,
                   const std::string& font);

// Pixel coordinates of the image's file -> canvas pixels under `view`.
Affine2 image_to_canvas(const Image& image, const ViewTransform& view);

enum class TextAlign { left, center, right };
// Draws `text` with its box's top at y, aligned on x; with `markup`, the text
// is Pango markup ("F<sub>A</sub>"), else it is drawn as written.
void paint_text(cairo_t* cr, const std::string& text, const std::string& font, double size,
                const Color& color, double x, double y, TextAlign align, bool markup = false);

// Whether a label's text is drawn as Pango markup: it has a '<' and parses as
// markup. Any other text (no tag, or "a < b") is drawn as written, so plain
// labels are unchanged (README "label").
bool is_markup(const std::string& text);

}  // namespace pita::render
