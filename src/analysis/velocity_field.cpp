#include "analysis/velocity_field.hpp"

#include <algorithm>

#include "core/finite_difference.hpp"

namespace pita::analysis {

FieldCheck check_integral_curves(const SamVelocityField& field, std::span<const Eigen::Vector2d> starts,
                                 std::span<const double> times) {
  FieldCheck check;
  double worst = 0.0;
  const double h = kFieldStep;
  for (const Eigen::Vector2d& x0 : starts) {
    for (const double u : times) {
      const auto x = [&](double v) { return field.trajectory(x0, v); };
      const Eigen::Vector2d derivative = central_derivative4(x, u, h);
      const Eigen::Vector2d velocity = field.at(x(u));
      worst = std::max(worst, (derivative - velocity).norm());
      check.largest_speed = std::max(check.largest_speed, velocity.norm());
      ++check.samples;
    }
  }
  check.deviation = check.largest_speed > 0.0 ? worst / check.largest_speed : worst;
  return check;
}

}  // namespace pita::analysis
