// Drawings as numbers (src/render/drawing.cpp): the box of every shape's
// points and the finiteness check.
#include <limits>

#include <gtest/gtest.h>

#include "render/drawing.hpp"

namespace pita::render {
namespace {

Item item(Shape shape) { return {"/layers/0", -1, std::move(shape)}; }

TEST(Drawing, BoundsHoldEveryPointOfEveryShape) {
  Drawing d;
  d.items.push_back(item(Polyline{{{0.0, 0.0}, {2.0, -1.0}}, false, {}}));
  d.items.push_back(item(FilledPath{{{{-3.0, 0.5}, {0.0, 4.0}, {1.0, 1.0}}}, {}, 1.0, {}}));
  d.items.push_back(item(ArrowShape{{5.0, 0.0}, {6.0, 0.5}, {}}));
  const auto box = bounds(d);
  ASSERT_TRUE(box.has_value());
  EXPECT_EQ(box->min, (Point{-3.0, -1.0}));
  EXPECT_EQ(box->max, (Point{6.0, 4.0}));
}

// Circles count by their centre, labels by their anchor: a huge discrepancy
// circle must not shrink the figure.
TEST(Drawing, CirclesAndLabelsCountByTheirCentre) {
  Drawing d;
  d.items.push_back(item(Circle{{1.0, 2.0}, 1e6, {}, {}}));
  d.items.push_back(item(Label{"x", {-1.0, 3.0}, 12.0, {}}));
  const auto box = bounds(d);
  ASSERT_TRUE(box.has_value());
  EXPECT_EQ(box->min, (Point{-1.0, 2.0}));
  EXPECT_EQ(box->max, (Point{1.0, 3.0}));
}

TEST(Drawing, EmptyDrawingHasNoBounds) {
  EXPECT_FALSE(bounds(Drawing{}).has_value());
  Drawing only_legend;
  only_legend.legends.push_back(Legend{});
  EXPECT_FALSE(bounds(only_legend).has_value());
  EXPECT_TRUE(is_finite(Drawing{}));
}

TEST(Drawing, IsFiniteFindsANonFiniteCoordinateInAnyShape) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Drawing good;
  good.items.push_back(item(Polyline{{{0.0, 0.0}, {1.0, 1.0}}, true, {}}));
  good.items.push_back(item(Circle{{0.0, 0.0}, 2.0, {}, {}}));
  EXPECT_TRUE(is_finite(good));
  const Shape bad_shapes[] = {
      Polyline{{{0.0, 0.0}, {nan, 1.0}}, false, {}},
      FilledPath{{{{0.0, 0.0}, {1.0, 0.0}}, {{0.0, inf}}}, {}, 1.0, {}},
      Circle{{0.0, 0.0}, inf, {}, {}},
      ArrowShape{{0.0, 0.0}, {1.0, -inf}, {}},
      Label{"x", {nan, 0.0}, 12.0, {}},
  };
  for (const Shape& shape : bad_shapes) {
    Drawing bad = good;
    bad.items.push_back(item(shape));
    EXPECT_FALSE(is_finite(bad)) << "shape " << shape.index();
  }
}

}  // namespace
}  // namespace pita::render
