// The "existence" layer (src/render/layers/existence.cpp, SAM Fig. 6),
// checked against SAM Eq. 4 computed here.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "analysis/existence.hpp"
#include "render/layers/existence.hpp"

namespace pita::render {
namespace {

// Fig. 6: the filled cells are exactly those outside SAM Eq. 4's boundary.
TEST(ExistenceLayer, RegionIsEquationFour) {
  scene::ExistenceLayer layer;
  layer.columns = 180;
  layer.rows = 90;
  layer.exists_fill.reset();
  const Drawing drawing = existence_drawing(layer, "/layers/0");
  const auto& bad = std::get<FilledPath>(drawing.items.at(0).shape);
  const auto filled = [&](double a, double y) {
    for (const auto& rectangle : bad.contours) {
      if (a > rectangle[0].real() && a < rectangle[1].real() && y > rectangle[0].imag() && y < rectangle[2].imag()) {
        return true;
      }
    }
    return false;
  };
  int checked = 0, red = 0;
  for (int j = 0; j < layer.rows; ++j) {
    const double s = (j + 0.5) / layer.rows;
    const double boundary = std::acos(-2.0 * s / (s * s + 1.0));  // SAM Eq. 4
    for (int i = 0; i < layer.columns; ++i) {
      const double a = -kPi + (i + 0.5) * 2.0 * kPi / layer.columns;
      if (std::abs(std::abs(a) - boundary) < 1e-9) continue;
      const bool no_sam = std::abs(a) > boundary;
      EXPECT_EQ(filled(a, kExistenceHeight * s), no_sam) << "a = " << a << ", s = " << s;
      red += no_sam;
      ++checked;
    }
  }
  EXPECT_EQ(checked, layer.columns * layer.rows);
  EXPECT_GT(red, checked / 20);
  // The trapezoid |a| < (1 + s) pi/2 lies in the region where a SAM exists.
  for (int j = 0; j <= 100; ++j) {
    const double s = j / 100.0;
    EXPECT_LE((1.0 + s) * kPi / 2.0, std::acos(-2.0 * s / (s * s + 1.0)) + 1e-12);
  }
}

}  // namespace
}  // namespace pita::render
