#include "analysis/velocity_field.hpp"

#include <algorithm>

namespace pita::analysis {

FieldCheck check_integral_curves(const SamVelocityField& field, std::span<const Eigen::Vector2d> starts,
                                 std::span<const double> times) {
  FieldCheck check;
  double worst = 0.0;
  const double h = kFieldStep;
  for (const Eigen::Vector2d& x0 : starts) {
    for (const double u : times) {
      const auto x = [&](double k) { return field.trajectory(x0, u + k * h); };
      // f'(u) ~ (f(u - 2h) - 8 f(u - h) + 8 f(u + h) - f(u + 2h)) / (12 h)
      const Eigen::Vector2d derivative = (x(-2) - 8.0 * x(-1) + 8.0 * x(1) - x(2)) / (12.0 * h);
      const Eigen::Vector2d velocity = field.at(x(0));
      worst = std::max(worst, (derivative - velocity).norm());
      check.largest_speed = std::max(check.largest_speed, velocity.norm());
      ++check.samples;
    }
  }
  check.deviation = check.largest_speed > 0.0 ? worst / check.largest_speed : worst;
  return check;
}

}  // namespace pita::analysis
