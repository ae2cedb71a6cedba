// Steady morph between two arrows (SMA) and the steady average (Sec. 2.5).
#pragma once

#include "core/arrow.hpp"
#include "core/twirl.hpp"

namespace pita {

// M(A, B, t) = T_{A,B}^t . A (PITA Eq. 20): M(A, B, 0) = A, M(A, B, 1) = B; any
// real t extrapolates along the same log-spiral motion.
// Evaluated from the nearer end: M(A, B, t) = M(B, A, 1 - t) (the SMA is
// symmetric, windings included), so that M(A, B, 1) is B itself and a far
// extrapolated A (P9's Neville steps, docs/paper-notes.md N36) does not
// swamp the frames near B with its rounding.
inline Arrow steady_morph(const Arrow& A, const Arrow& B, double t) {
  if (t > 0.5) return apply_power(twirl_between(B, A), 1.0 - t, B);
  return apply_power(twirl_between(A, B), t, A);
}

// The timed SMA M(a, A, b, B, t) = M(A, B, (t - a)/(b - a)) (PITA Eq. 21).
inline Arrow steady_morph(double a, const Arrow& A, double b, const Arrow& B, double t) {
  return steady_morph(A, B, (t - a) / (b - a));
}

// The steady average M(A, B) = M(A, B, 1/2) (PITA Eq. 23). Symmetric: M(A, B) = M(B, A).
// At t = 1/2 the anchor's progress has the closed form
//   phi_{1/2}(L) = (e^{L/2} - 1)/(e^L - 1) = 1/(e^{L/2} + 1),
// so one square root and one sincos suffice (P6 calls this every frame).
inline Arrow steady_average(const Arrow& A, const Arrow& B) {
  const double root = std::sqrt(B.m / A.m);
  const double half_turn = 0.5 * (B.w - A.w);
  const Complex h = std::polar(root, half_turn);  // e^{L/2}
  const Complex den = (h - 1.0) * (h + 1.0);      // e^L - 1, for the fallback test
  const bool translation = std::norm(den) < limits::kTwirlTranslation * limits::kTwirlTranslation;
  const Complex progress = translation ? Complex{0.5} : 1.0 / (h + 1.0);
  return {A.p + progress * (B.p - A.p), A.m * root, A.w + half_turn};
}

}  // namespace pita
