#include "core/instant_center.hpp"

#include <cmath>

#include "core/limits.hpp"

namespace pita {

std::optional<Point> field_zero(Point p, Vector v, Vector dp, Vector dv) {
  if (dv == Vector{0.0, 0.0}) return std::nullopt;
  const Vector offset = dp * v / dv;  // x - p at the zero, negated
  if (!std::isfinite(offset.real()) || !std::isfinite(offset.imag())) return std::nullopt;
  if (std::abs(offset) > limits::kFarCenter * std::abs(v)) return std::nullopt;
  return p - offset;
}

}  // namespace pita
