#include "core/pitas/independent.hpp"

#include "core/vector_motions.hpp"

namespace pita {

IndependentPita::IndependentPita(const KeyframeTriple& k, PointMotion point, VectorMotion vector)
    : k_(k), point_(point), vector_(vector), spiral_(k.a.arrow.p, k.b.arrow.p, k.c.arrow.p) {}

Arrow IndependentPita::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  const Arrow& A = k_.a.arrow;
  const Arrow& B = k_.b.arrow;
  const Arrow& C = k_.c.arrow;
  const Point p = point_ == PointMotion::parabola ? parabolic_point(l, A.p, B.p, C.p) : spiral_.at(l);
  switch (vector_) {
    case VectorMotion::cartesian:
      return arrow_from_vector(p, cartesian_vector(l, A, B, C));
    case VectorMotion::polar: {
      const PolarVector v = polar_vector(l, A, B, C);
      return {p, v.m, v.w};
    }
    case VectorMotion::log_polar: {
      const PolarVector v = log_polar_vector(l, A, B, C);
      return {p, v.m, v.w};
    }
  }
  return {};
}

}  // namespace pita
