// Lagrange interpolation of three timed values (Sec. 2.3).
#pragma once

namespace pita {

// Weights (x, y, z) of the quadratic Lagrange interpolant through knots a, b, c
// (PITA Eq. 10): v(t) = x v_a + y v_b + z v_c (PITA Eq. 9), x + y + z = 1.
struct LagrangeWeights {
  double x;
  double y;
  double z;
};

inline LagrangeWeights lagrange_weights(double a, double b, double c, double t) {
  return {(t - b) / (a - b) * ((t - c) / (a - c)),  //
          (t - a) / (b - a) * ((t - c) / (b - c)),  //
          (t - a) / (c - a) * ((t - b) / (c - b))};
}

// PITA Eq. 9 for any value type with + and scalar *.
template <class V>
V lagrange(const LagrangeWeights& l, const V& va, const V& vb, const V& vc) {
  return l.x * va + l.y * vb + l.z * vc;
}

}  // namespace pita
