// Comparing the numbers of two figure data files (figure_data.hpp): the
// structure must be identical (same panels, items, kinds and point counts),
// and every number may differ by at most `relative` times its panel's extent.
#pragma once

#include <string>

#include "golden/figure_data.hpp"

namespace pita::golden {

inline constexpr double kDefaultNumberTolerance = 1e-9;  // of the panel's extent

struct NumberComparison {
  bool matches = true;
  std::string structure;  // non-empty when the structures differ: what and where
  // The worst offender (largest relative difference), when structures agree.
  std::string pointer;  // JSON Pointer in the data file, "/panels/0/items/12/polyline/1/0"
  std::string panel;    // the panel's scene pointer ("" for the scene itself)
  std::string layer;    // the item's layer pointer, "/layers/0"
  int index = -1;       // the item's frame (or keyframe) index
  double expected = 0.0, actual = 0.0;
  double relative = 0.0;      // |actual - expected| / extent
  std::size_t compared = 0;   // numbers compared
  std::size_t differing = 0;  // numbers beyond the tolerance
};

NumberComparison compare_numbers(const Json& expected, const Json& actual, double relative);

// "the number at /panels/0/items/12/polyline/1/0 (layer /layers/0, frame 12) is 3.2 instead of
// 3.1 (1.4e-2 of the panel's extent; tolerance 1e-9)", or the structural difference.
std::string describe(const NumberComparison& c, double relative);

}  // namespace pita::golden
