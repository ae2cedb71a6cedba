// Velocities and accelerations of the moving frame D(t) of an arrow scene
// (PITA Sec. 3.3 and 4.11, Figs. 9, 14, 15; docs/paper-notes.md N40), and the
// instantaneous centers of the motion they define (core/instant_center.hpp).
//
// The motions offer no derivatives of their own, so they are finite
// differences of D at scene times, fourth order (core/finite_difference.hpp)
// with the step h = (knot span) / 256, taken on the knot span that holds t
// (the piece before the first knot or after the last one when t is outside,
// with h = (last - first) / 256): a stencil never straddles a knot, where the
// knot warp of P4/P7/P8 and a per-span ease are only C1. Inside a span the
// five centered nodes t + h {-2..2}; where they would leave it, six nodes
// h apart shifted into it (still fourth order). At a knot the derivative is
// that of the span after it (of the one before it at the last knot).
#pragma once

#include <optional>

#include "core/arrow.hpp"
#include "core/limits.hpp"
#include "motion/scene_motion.hpp"

namespace pita::analysis {

struct FrameDerivatives {
  double t = 0.0;
  Point p, q;       // D(t).p, D(t).q
  Vector dp, dq;    // their velocities, per unit of scene time
  Vector ddp, ddq;  // their accelerations, per unit of scene time squared
};

// D and its first two derivatives at scene time t. Throws motion::NoMotion
// when the motion is undefined at a node of the stencil.
FrameDerivatives frame_derivatives(const motion::SceneMotion& motion, double t);

// The points of the plane whose velocity (velocity_center) or acceleration
// (acceleration_center) is zero at t; nullopt when the field is a pure
// translation (core/instant_center.hpp).
std::optional<Point> velocity_center(const FrameDerivatives& d);
std::optional<Point> acceleration_center(const FrameDerivatives& d);

}  // namespace pita::analysis
