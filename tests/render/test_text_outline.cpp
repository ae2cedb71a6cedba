// Sec. 7.3: a banner's outline lies inside the quad strip of its pattern, and
// the text keeps its shape where the strip is a rectangle.
#include <cmath>

#include <gtest/gtest.h>

#include "render/panel_drawing.hpp"
#include "render/strip.hpp"
#include "render/text_outline.hpp"
#include "render_support.hpp"
#include "support/keys.hpp"

namespace pita::render::test {
namespace {

// Is x inside the convex hull of the quad's corners (with a little slack)?
bool inside_hull(const std::array<Point, 4>& quad, Point x, double slack) {
  // Bilinear images of the unit square lie in the hull of the four corners:
  // test every half-plane of the hull's edges (hull by gift wrapping).
  std::vector<Point> pts(quad.begin(), quad.end());
  const auto cross = [](Point a, Point b, Point c) {
    return (b - a).real() * (c - a).imag() - (b - a).imag() * (c - a).real();
  };
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (i == j) continue;
      // (i, j) is a hull edge if every other point is on its left.
      bool edge = true;
      for (std::size_t k = 0; k < pts.size(); ++k) {
        if (k != i && k != j && cross(pts[i], pts[j], pts[k]) < 0.0) edge = false;
      }
      if (edge && cross(pts[i], pts[j], x) < -slack * std::abs(pts[j] - pts[i])) return false;
    }
  }
  return true;
}

TEST(TextOutline, HasContoursInsideItsInkBox) {
  const TextOutline outline = text_outline("PITA", "Sans Bold");
  ASSERT_GE(outline.contours.size(), 4u);  // P (2), I, T, A (2)
  const double h = outline.bottom - outline.top;
  for (const auto& contour : outline.contours) {
    for (Point x : contour) {
      EXPECT_GE(x.real(), outline.left - 1e-3 * h);
      EXPECT_LE(x.real(), outline.right + 1e-3 * h);
      EXPECT_GE(x.imag(), outline.top - 1e-3 * h);
      EXPECT_LE(x.imag(), outline.bottom + 1e-3 * h);
    }
  }
}

TEST(TextOutline, LongEdgesAreSubdivided) {
  const TextOutline outline = text_outline("I", "Sans");
  const double h = outline.bottom - outline.top;
  for (const auto& contour : outline.contours) {
    for (std::size_t k = 0; k < contour.size(); ++k) {
      EXPECT_LE(std::abs(contour[(k + 1) % contour.size()] - contour[k]), kBannerMaxEdge * h * 1.0001);
    }
  }
}

TEST(Banner, OutlinePointsLieInsideTheStrip) {
  const scene::Panel p = panel(Method::P6, three_keyframes(), 21);
  scene::BannerLayer layer;
  layer.text = "Warped banner";
  layer.padding = 0.1;
  const Drawing d = panel_drawing(scene_with({layer}, {p}), p);
  const auto* glyphs = std::get_if<FilledPath>(&d.items.at(0).shape);
  ASSERT_NE(glyphs, nullptr);
  ASSERT_GT(glyphs->contours.size(), 10u);
  const auto motion = make_motion(track_keys(p).method, arrow_keys(p).keyframes);
  std::vector<Arrow> frames;
  for (int i = 0; i < 21; ++i) frames.push_back(motion->at(i / 20.0));
  const QuadStrip strip(frames);
  std::size_t points = 0;
  for (const auto& contour : glyphs->contours) {
    for (Point x : contour) {
      bool inside = false;
      for (int i = 0; i < strip.quad_count() && !inside; ++i) inside = inside_hull(strip.quad(i), x, 1e-9);
      EXPECT_TRUE(inside) << x;
      ++points;
    }
  }
  EXPECT_GT(points, 500u);
}

TEST(Banner, RectangularStripKeepsTheTextProportional) {
  // Vertical arrows of length 1 along the x axis from 0 to 10: the strip is
  // the rectangle [0, 10] x [0, 1], and the map is affine.
  std::vector<Arrow> frames;
  for (int i = 0; i <= 10; ++i) frames.push_back(Arrow{{static_cast<double>(i), 0.0}, 1.0, std::numbers::pi / 2});
  const QuadStrip strip(frames);
  const TextOutline outline = text_outline("Hi", "Sans");
  const auto mapped = map_through_strip(outline, strip, 0.2);
  const double w = outline.right - outline.left, h = outline.bottom - outline.top;
  for (std::size_t c = 0; c < mapped.size(); ++c) {
    for (std::size_t k = 0; k < mapped[c].size(); ++k) {
      const Point x = outline.contours[c][k];
      const Point expected{(x.real() - outline.left) / w * 10.0, 0.8 - 0.6 * (x.imag() - outline.top) / h};
      EXPECT_NEAR(std::abs(mapped[c][k] - expected), 0.0, 1e-12);
    }
  }
}

}  // namespace
}  // namespace pita::render::test
