// Timed keyframes: an arrow and the knot (time value) at which a motion must
// pass through it (Sec. 1).
#pragma once

#include "core/arrow.hpp"

namespace pita {

struct Keyframe {
  double t = 0.0;  // knot
  Arrow arrow;
};

// The three timed keyframes (a, A), (b, B), (c, C) of a PITA. The knots must be
// distinct; the registry requires a < b < c, the PITA functions themselves
// accept any distinct knots (the order-independence test of PITA Eq. 42 needs it).
struct KeyframeTriple {
  Keyframe a;
  Keyframe b;
  Keyframe c;
};

}  // namespace pita
