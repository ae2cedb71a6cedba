// The discrepancy E(A, B) between two arrows (Sec. 6.2, PITA Eq. 44-47), a
// similarity-invariant measure of how far apart two oriented segments are.
#pragma once

#include "core/arrow.hpp"

namespace pita {

// Coordinates of point x in the frame of the segment from a to b, in units of
// |b - a|: x along (PITA Eq. 44), y across (PITA Eq. 45, R the rotation by pi/2). As
// complex numbers (x + i y) = (x_point - a) / (b - a).
inline Complex segment_coordinates(Point a, Point b, Point x) { return (x - a) / (b - a); }

// z(a, b, p) = x^2 + y^2 (PITA Eq. 46) = |p - a|^2 / |b - a|^2.
inline double segment_z(Point a, Point b, Point x) { return std::norm(segment_coordinates(a, b, x)); }

// E(A, B) (PITA Eq. 47, last term read z(d, c, b), docs/paper-notes.md N5), with
// a = A.p, b = A.q, c = B.p, d = B.q:
//     E = z(a, b, c) + z(b, a, d) + z(c, d, a) + z(d, c, b)
//       = (|c - a|^2 + |d - b|^2) (1 / A.m^2 + 1 / B.m^2).
// Zero iff the segments coincide; symmetric; invariant under similarities.
inline double discrepancy(const Arrow& A, const Arrow& B) {
  const Point a = A.p, b = A.q(), c = B.p, d = B.q();
  return segment_z(a, b, c) + segment_z(b, a, d) + segment_z(c, d, a) + segment_z(d, c, b);
}

}  // namespace pita
