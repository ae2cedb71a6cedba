// The carrier similarity of PITA Sec. 7.1 ("designing the motion of an
// image"): the designer draws a handle arrow E over a picture X; the picture
// then moves with the frame D(t) so that (X, E) ~ (X_t, D(t)): X_t is X mapped
// by the direct similarity that takes E onto D(t). Only the arrows' start and
// end points matter (a similarity has no turns), so the winding of D(t) is
// irrelevant here (docs/paper-notes.md N35).
#pragma once

#include "core/affine2.hpp"
#include "core/arrow.hpp"

namespace pita {

// The direct similarity S with S(E.p) = D.p and S(E.q) = D.q:
//   S(z) = D.p + (D.q - D.p) / (E.q - E.p) * (z - E.p)        (Sec. 7.1)
// E must have a nonzero vector (E.m > 0); the result is then finite whenever
// E and D are.
inline Affine2 carrier(const Arrow& handle, const Arrow& frame) {
  const Complex ratio = frame.vector() / handle.vector();  // (D.q - D.p) / (E.q - E.p)
  Affine2 S;
  S.L << ratio.real(), -ratio.imag(), ratio.imag(), ratio.real();
  const Point b = frame.p - ratio * handle.p;
  S.b << b.real(), b.imag();
  return S;
}

}  // namespace pita
