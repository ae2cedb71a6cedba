// Points, vectors and arrows (Sec. 2.1).
//
// Points and vectors of the plane are complex numbers: x + iy. An arrow
// A(p, m, w) starts at p, has magnitude m > 0 and winding w, an arbitrary real
// angle that is never reduced modulo 2*pi: w = 0.3 and w = 0.3 + 2*pi are the
// same segment but different arrows (the second one carries one more turn).
#pragma once

#include <cmath>
#include <complex>
#include <numbers>

#include "core/complex_math.hpp"

namespace pita {

using Point = Complex;
using Vector = Complex;

inline Point make_point(double x, double y) { return {x, y}; }

struct Arrow {
  Point p{};       // origin (start point)
  double m = 1.0;  // magnitude, > 0 for keyframes
  double w = 0.0;  // winding: any real angle, never reduced

  // The vector of the arrow, V_pol(m, w) = m e^{iw}.
  Vector vector() const { return std::polar(m, w); }
  // The end point q = p + vector (Sec. 2.1).
  Point q() const { return p + vector(); }
  // The integer winding count k with |w - 2 k pi| <= pi (Abstract).
  long turns() const { return std::lround(w / (2.0 * std::numbers::pi)); }
  // Complex form of the linear part, m e^{iw}; equal for w and w + 2*pi.
  Complex linear() const { return vector(); }
};

// The arrow from p with magnitude and winding of vector v: A(p, v) (Sec. 2.1).
// v is taken as a zero-turn vector: winding = Arg v in (-pi, pi].
inline Arrow arrow_from_vector(Point p, Vector v) { return {p, std::abs(v), std::arg(v)}; }

// The zero-turn arrow "pq" from point p to point q (Sec. 2.1).
inline Arrow zero_turn_arrow(Point p, Point q) { return arrow_from_vector(p, q - p); }

// The same segment with its winding reduced to (-pi, pi].
inline Arrow zero_turn(const Arrow& a) { return {a.p, a.m, principal_angle(a.w)}; }

// Adds k whole turns (2 pi k) to the winding: same segment, more turns.
inline Arrow with_turns(const Arrow& a, double k) { return {a.p, a.m, a.w + 2.0 * std::numbers::pi * k}; }

// The extended form e(A), from p - vector to q (Sec. 2.1).
struct Segment {
  Point from;
  Point to;
};
inline Segment extended_form(const Arrow& a) { return {a.p - a.vector(), a.q()}; }

inline bool is_finite(const Arrow& a) {
  return std::isfinite(a.p.real()) && std::isfinite(a.p.imag()) && std::isfinite(a.m) && std::isfinite(a.w);
}

}  // namespace pita
