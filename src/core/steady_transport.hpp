// Steady transport of an arrow (STA, Sec. 2.6).
#pragma once

#include "core/arrow.hpp"
#include "core/twirl.hpp"

namespace pita {

// T(C, A, B, t) = T_{A,B}^t . C (PITA Eq. 24): moves C by the similarity of the
// steady morph from A to B at time t.
inline Arrow steady_transport(const Arrow& C, const Arrow& A, const Arrow& B, double t) {
  return apply_power(twirl_between(A, B), t, C);
}

// The timed STA T(C, a, A, b, B, t) = T(C, A, B, (t - a)/(b - a)) (PITA Eq. 25).
inline Arrow steady_transport(const Arrow& C, double a, const Arrow& A, double b, const Arrow& B, double t) {
  return steady_transport(C, A, B, (t - a) / (b - a));
}

}  // namespace pita
