// The check of a SAM's integral curves against its field
// (src/analysis/velocity_field.cpp; SAM Fig. 8): the SAM's trajectories
// follow its field to the accuracy of the finite differences.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/velocity_field.hpp"

namespace pita::analysis {
namespace {

Affine2 spiral(double angle, double scale, Eigen::Vector2d q) {
  Affine2 A;
  A.L << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  A.L *= scale;
  A.L(0, 1) += 0.3;  // a shear too
  A.b = q - A.L * q;
  return A;
}

TEST(VelocityField, SamTrajectoriesFollowTheField) {
  const SamVelocityField field(spiral(1.9, 1.2, {3.0, 2.0}));
  const std::vector<Eigen::Vector2d> starts{{0.0, 0.0}, {6.0, 5.0}, {-1.0, 4.0}};
  const std::vector<double> times{0.0, 0.25, 0.5, 0.75, 1.0};
  const FieldCheck check = check_integral_curves(field, starts, times);
  EXPECT_EQ(check.samples, 15);
  EXPECT_GT(check.largest_speed, 1.0);
  EXPECT_LT(check.deviation, 1e-9);
}

}  // namespace
}  // namespace pita::analysis
