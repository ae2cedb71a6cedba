// The "sam3d-existence" layer (src/render/layers/sam3d_existence.cpp, SAM
// Sec. 5.2): the staircase of a given curve, the paper's bounds, and the
// computed curve drawn.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "analysis/sam3d_existence.hpp"
#include "render/layers/sam3d_existence.hpp"

namespace pita::render {
namespace {

// "sam3d-existence" draws a given curve as a staircase at y = 5 p, marks the
// curve's value at each of the paper's three angles (the angles up to it) and
// says where it differs from the paper's bound.
TEST(Sam3dExistenceLayer, DrawsTheStaircaseAndThePapersBounds) {
  analysis::SafeCurve curve;
  curve.thetas = {0.0, kPi / 4.0, kPi / 2.0, 3.0 * kPi / 4.0, kPi};
  curve.largest_p = {0.33, 0.33, 0.29, 0.2, 0.0};
  const scene::Sam3dExistenceLayer layer;
  const Drawing drawing = sam3d_existence_drawing(layer, curve, "/layers/0");
  const Polyline* stairs = nullptr;
  std::vector<const Circle*> marks;
  std::vector<std::string> claims;
  for (const Item& item : drawing.items) {
    EXPECT_EQ(item.layer, "/layers/0");
    if (const auto* line = std::get_if<Polyline>(&item.shape); line && line->line.color == layer.line.color) {
      stairs = line;
    }
    if (const auto* circle = std::get_if<Circle>(&item.shape)) marks.push_back(circle);
    if (const auto* label = std::get_if<Label>(&item.shape);
        label && label->text.find("paper p <") != std::string::npos) {
      claims.push_back(label->text);
    }
  }
  ASSERT_NE(stairs, nullptr);
  // Each value held from its angle to the next: (theta_k, 5 p_k), (theta_k+1, 5 p_k).
  ASSERT_EQ(stairs->points.size(), 2u * curve.thetas.size() - 1u);
  for (std::size_t k = 0; k < curve.thetas.size(); ++k) {
    EXPECT_NEAR(stairs->points[2 * k].real(), curve.thetas[k], 1e-15);
    EXPECT_NEAR(stairs->points[2 * k].imag(), 5.0 * curve.largest_p[k], 1e-15);
    if (k + 1 < curve.thetas.size()) {
      EXPECT_NEAR(stairs->points[2 * k + 1].real(), curve.thetas[k + 1], 1e-15);
      EXPECT_NEAR(stairs->points[2 * k + 1].imag(), 5.0 * curve.largest_p[k], 1e-15);
    }
  }
  // 2 pi/3: the angles up to pi/2 count, 0.29 = 0.29; pi/2: 0.29 < 0.33;
  // pi/4: 0.33 < 0.50.
  ASSERT_EQ(marks.size(), 3u);
  EXPECT_NEAR(marks[0]->center.imag(), 5.0 * 0.29, 1e-12);
  EXPECT_NEAR(marks[1]->center.imag(), 5.0 * 0.29, 1e-12);
  EXPECT_NEAR(marks[2]->center.imag(), 5.0 * 0.33, 1e-12);
  ASSERT_EQ(claims.size(), 3u);
  EXPECT_EQ(claims[0].find("differs"), std::string::npos) << claims[0];
  EXPECT_NE(claims[1].find("ours 0.29 (differs)"), std::string::npos) << claims[1];
  EXPECT_NE(claims[2].find("paper p < 0.50, ours 0.33 (differs)"), std::string::npos) << claims[2];

  scene::Sam3dExistenceLayer quiet;
  quiet.paper = false;
  quiet.fill.reset();
  for (const Item& item : sam3d_existence_drawing(quiet, curve, "/layers/0").items) {
    EXPECT_FALSE(std::holds_alternative<Circle>(item.shape));
    EXPECT_FALSE(std::holds_alternative<FilledPath>(item.shape));
  }
}

// Computed: the curve of analysis/sam3d_existence.hpp, drawn.
TEST(Sam3dExistenceLayer, ComputesTheCurve) {
  scene::Sam3dExistenceLayer layer;
  layer.steps = 2;
  layer.subdivisions = 0;
  analysis::Sam3dExistenceOptions options;
  options.subdivisions = 0;
  const analysis::SafeCurve curve = analysis::largest_safe_perturbation_curve(2, options);
  const Drawing computed = sam3d_existence_drawing(layer, "/layers/0");
  const Drawing given = sam3d_existence_drawing(layer, curve, "/layers/0");
  ASSERT_EQ(computed.items.size(), given.items.size());
  for (std::size_t i = 0; i < given.items.size(); ++i) {
    if (const auto* line = std::get_if<Polyline>(&given.items[i].shape)) {
      EXPECT_EQ(std::get<Polyline>(computed.items[i].shape).points, line->points);
    }
  }
  EXPECT_NEAR(curve.largest_p[0], 0.33, 1e-12);  // I - p J
}

}  // namespace
}  // namespace pita::render
