// Sec. 7.3, Fig. 26: a text laid out with pango, turned into outlines, and
// mapped through a pattern's quad strip. Each outline is flattened (curves
// become polylines within kBannerTolerance of the text height) and its long
// edges are subdivided, so that the letters bend smoothly with the strip.
#pragma once

#include <string>
#include <vector>

#include "render/strip.hpp"

namespace pita::render {

inline constexpr double kBannerTolerance = 1e-3;  // flattening, in units of the text height
inline constexpr double kBannerMaxEdge = 2e-2;    // longest edge before mapping, same units

// The text's outline contours in layout units, y down, as pango draws them
// with `font` (a pango font description; its size is ignored).
struct TextOutline {
  std::vector<std::vector<Point>> contours;
  // The box mapped onto the strip: horizontally the ink (the outline's own
  // extent), vertically the line's logical box (so that every text shares a
  // baseline), both grown to hold every outline point.
  double left = 0.0, top = 0.0, right = 0.0, bottom = 0.0;
};
TextOutline text_outline(const std::string& text, const std::string& font);

// The contours mapped into the strip: the ink box's left edge goes to u = 0,
// its right edge to u = n - 1, its top to v = 1 - padding (the q side) and its
// bottom to v = padding.
std::vector<std::vector<Point>> map_through_strip(const TextOutline& outline, const QuadStrip& strip, double padding);

}  // namespace pita::render
