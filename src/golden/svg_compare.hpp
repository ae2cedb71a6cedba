// Comparing SVG figures by their geometry, not their bytes: the numbers of
// every drawing element (path data, positions, sizes, transforms, widths) are
// read in document order, outside <defs> (cairo's glyph outlines, which depend
// on the font files rather than on the figure), and compared with an
// absolute tolerance in pixels. A newer cairo that writes "0.5" as ".5" or
// reorders attributes still matches; a moved frame does not.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pita::golden {

inline constexpr double kDefaultSvgTolerance = 1e-3;  // pixels

// The numbers of the SVG's drawing, in order.
std::vector<double> svg_numbers(std::string_view svg);

struct SvgComparison {
  bool matches = true;
  std::size_t expected_count = 0, actual_count = 0;
  std::size_t worst = 0;  // index of the number that differs most
  double expected = 0.0, actual = 0.0, difference = 0.0;
  std::size_t differing = 0;
};

SvgComparison compare_svg(std::string_view expected, std::string_view actual, double tolerance);

std::string describe(const SvgComparison& c, double tolerance);

}  // namespace pita::golden
