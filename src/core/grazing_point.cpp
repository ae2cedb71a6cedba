#include "core/grazing_point.hpp"

#include <cmath>

#include "core/limits.hpp"

namespace pita {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// s = -n . w0 / n . w1 with n . w = cross(t, w), t the edge's direction at the
// instant; none when the quotient is beyond kFarGrazingPoint (the denominator
// zero included).
std::optional<double> quotient(const Eigen::Vector2d& t, const Eigen::Vector2d& w0, const Eigen::Vector2d& w1) {
  const double numerator = cross(t, w0);
  const double denominator = cross(t, w1);
  if (!(std::abs(numerator) < limits::kFarGrazingPoint * std::abs(denominator))) return std::nullopt;
  return -numerator / denominator;
}

}  // namespace

std::optional<double> grazing_parameter(const Affine2& pose, const Affine2& velocity, const Edge& edge) {
  const Eigen::Vector2d d = edge.to - edge.from;
  // n . (L' from + c') + s n . (L' d) = 0 with n = J L d.
  return quotient(pose.L * d, velocity.L * edge.from + velocity.b, velocity.L * d);
}

std::optional<double> sam_grazing_parameter(const Affine2& generator, const Affine2& first, const Edge& edge) {
  // SAM Eq. 8 at t = 0: q = B(from), t = L_B d, the field x -> C x + v.
  const Eigen::Vector2d q = apply(first, edge.from);
  const Eigen::Vector2d t = first.L * (edge.to - edge.from);
  return quotient(t, generator.L * q + generator.b, generator.L * t);
}

}  // namespace pita
