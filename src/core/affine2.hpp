// Affinities of the plane (Sec. 3.3 and 4.10): x -> L x + b, with a 2x2
// linear part L and a translation b. A keyframe "triangle" of PAM (PITA Eq. 37-39)
// is an affinity; an arrow is the special case of a similarity (affine_of).
//
// The verbs are the ones every value type of the core shares, under the same
// names, so that generic code calls any of them: apply, compose, inverse here;
// pow, log, exp in affine_power.hpp (EAR). Twirl (twirl.hpp) has the same six.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include "core/arrow.hpp"

namespace pita {

struct Affine2 {
  Eigen::Matrix2d L = Eigen::Matrix2d::Identity();  // linear part
  Eigen::Vector2d b = Eigen::Vector2d::Zero();      // translation

  static Affine2 identity() { return {}; }
};

// The image of point x: L x + b.
inline Eigen::Vector2d apply(const Affine2& A, const Eigen::Vector2d& x) { return A.L * x + A.b; }

// The image of a point of the plane (a complex number), as the drawing layers
// and the motion stage need it.
inline Point apply(const Affine2& A, Point p) {
  const Eigen::Vector2d x = apply(A, Eigen::Vector2d(p.real(), p.imag()));
  return {x.x(), x.y()};
}

// A o B: first B, then A (x -> A(B(x))), the order of homogeneous matrices.
inline Affine2 compose(const Affine2& A, const Affine2& B) { return {A.L * B.L, A.L * B.b + A.b}; }

// The inverse affinity x -> L^-1 (x - b). Precondition: L invertible (no
// check: a singular L gives non-finite entries).
inline Affine2 inverse(const Affine2& A) {
  const Eigen::Matrix2d Li = A.L.inverse();
  return {Li, -Li * A.b};
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
