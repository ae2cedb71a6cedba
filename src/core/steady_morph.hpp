// Steady morph between two arrows (SMA) and the steady average (Sec. 2.5).
#pragma once

#include "core/arrow.hpp"
#include "core/twirl.hpp"

namespace pita {

// M(A, B, t) = T_{A,B}^t . A (Eq. 20): M(A, B, 0) = A, M(A, B, 1) = B; any
// real t extrapolates along the same log-spiral motion.
inline Arrow steady_morph(const Arrow& A, const Arrow& B, double t) {
  return apply_power(twirl_between(A, B), t, A);
}

// The timed SMA M(a, A, b, B, t) = M(A, B, (t - a)/(b - a)) (Eq. 21).
inline Arrow steady_morph(double a, const Arrow& A, double b, const Arrow& B, double t) {
  return steady_morph(A, B, (t - a) / (b - a));
}

// The steady average M(A, B) = M(A, B, 1/2) (Eq. 23). Symmetric: M(A, B) = M(B, A).
inline Arrow steady_average(const Arrow& A, const Arrow& B) { return steady_morph(A, B, 0.5); }

}  // namespace pita
