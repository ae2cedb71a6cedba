// Helpers shared by the pose tests of the core (SAM paper).
#pragma once

#include "core/affine2.hpp"

namespace pita::test {

// x -> [[a, b], [c, d]] x + [x, y].
inline Affine2 pose(double a, double b, double c, double d, double x, double y) {
  Affine2 A;
  A.L << a, b, c, d;
  A.b << x, y;
  return A;
}

// The same, written as the rows of its 2 x 3 matrix [[a, b, tx], [c, d, ty]]
// (as scenes write "matrix").
inline Affine2 affinity(double a, double b, double tx, double c, double d, double ty) {
  return pose(a, b, c, d, tx, ty);
}

// |L_X - L_Y| + |b_X - b_Y| (Frobenius and Euclidean norms).
inline double distance(const Affine2& X, const Affine2& Y) { return (X.L - Y.L).norm() + (X.b - Y.b).norm(); }

// The SAM paper's Fig. 7 situation: no SAM from A to C (C o A^-1 has two
// negative eigenvalues), but SAMs A-B and B-C exist.
inline const Affine2 kFig7A = pose(1.0, 0.0, 0.0, 1.0, 0.0, 0.0);
inline const Affine2 kFig7B = pose(0.0, -1.6, 0.6, 0.0, 3.0, 3.0);
inline const Affine2 kFig7C = pose(-1.8, 0.0, 0.0, -0.55, 6.0, 0.0);

}  // namespace pita::test
