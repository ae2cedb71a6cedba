// Affinities of the plane (Affine2 = Affine<2>, affine.hpp) and what is
// particular to the plane: the image of a point given as a complex number,
// and the similarity of an arrow.
#pragma once

#include "core/affine.hpp"
#include "core/arrow.hpp"

namespace pita {

// The image of a point of the plane (a complex number), as the drawing layers
// and the motion stage need it.
inline Point apply(const Affine2& A, Point p) {
  const Eigen::Vector2d x = apply(A, Eigen::Vector2d(p.real(), p.imag()));
  return {x.x(), x.y()};
}

// The similarity of an arrow as an affinity: it maps the unit arrow from
// (0, 0) to (1, 0) onto the arrow, L = m R(w) and b = p. The winding is kept
// only modulo 2 pi (an affinity has no turns), as in P8 (Sec. 3.3).
inline Affine2 affine_of(const Arrow& a) {
  const Vector v = a.vector();  // m e^{iw}: multiplication by v is m R(w)
  Affine2 A;
  A.L << v.real(), -v.imag(), v.imag(), v.real();
  A.b << a.p.real(), a.p.imag();
  return A;
}

}  // namespace pita
