// How well a SAM's trajectories follow its velocity field (SAM paper Sec. 6.2,
// Fig. 8; docs/paper-notes.md N47): the field is stationary exactly when the
// velocity of every trajectory x(u) = A^u(x0), measured by finite differences
// of the sampled positions, equals the field at x(u) at every u. What the
// "field" layer prints under its figure.
#pragma once

#include <span>

#include <Eigen/Core>

#include "core/sam_velocity_field.hpp"

namespace pita::analysis {

struct FieldCheck {
  // max over starts and times of |x'(u) - field(x(u))|, x' by the centred
  // fourth-order difference of A^u(x0) with step kFieldStep, divided by the
  // largest |field(x(u))| met (a number without unit).
  double deviation = 0.0;
  double largest_speed = 0.0;  // that largest |field(x(u))|
  int samples = 0;             // starts x times compared
};

// The step of the finite differences (in u): the truncation error h^4 |x^(5)|
// and the rounding error eps |x| / h are both below 1e-10 relative for the
// fields of the figures (|log L| of order 1).
inline constexpr double kFieldStep = 1e-3;

FieldCheck check_integral_curves(const SamVelocityField& field, std::span<const Eigen::Vector2d> starts,
                                 std::span<const double> times);

}  // namespace pita::analysis
