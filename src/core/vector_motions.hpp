// The vector motions of the PITAs (Sec. 3.1-3.3): the last two letters of a
// mnemonic (-Ca, -Po, -LP; -Pe lives in perseverant.hpp).
#pragma once

#include <cmath>

#include "core/arrow.hpp"
#include "core/lagrange_weights.hpp"

namespace pita {

// A vector in polar form with a winding: m e^{iw}, w any real.
struct PolarVector {
  double m;
  double w;
};

// -Ca: Lagrange interpolation (PITA Eq. 9) of the Cartesian components of the
// zero-turn vectors. Not winding-aware.
inline Vector cartesian_vector(const LagrangeWeights& l, const Arrow& A, const Arrow& B, const Arrow& C) {
  return lagrange(l, A.vector(), B.vector(), C.vector());
}

// -Po: Lagrange interpolation of the polar coordinates (m, w). The magnitude
// is the quadratic through the three magnitudes; for very unequal magnitudes
// it can pass through zero (the arrow then points backwards: we report m as
// computed, so q = p + m e^{iw} always holds).
inline PolarVector polar_vector(const LagrangeWeights& l, const Arrow& A, const Arrow& B, const Arrow& C) {
  return {lagrange(l, A.m, B.m, C.m), lagrange(l, A.w, B.w, C.w)};
}

// -LP: Lagrange interpolation of the log-polar coordinates (ln m, w).
inline PolarVector log_polar_vector(const LagrangeWeights& l, const Arrow& A, const Arrow& B, const Arrow& C) {
  return {std::exp(lagrange(l, std::log(A.m), std::log(B.m), std::log(C.m))), lagrange(l, A.w, B.w, C.w)};
}

}  // namespace pita
