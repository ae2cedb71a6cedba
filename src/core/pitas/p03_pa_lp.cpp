#include "core/pitas/p03_pa_lp.hpp"

#include "core/point_motions.hpp"
#include "core/vector_motions.hpp"

namespace pita {

PaLp::PaLp(const KeyframeTriple& k) : k_(k) {}

Arrow PaLp::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  const PolarVector v = log_polar_vector(l, k_.a.arrow, k_.b.arrow, k_.c.arrow);
  return {parabolic_point(l, k_.a.arrow.p, k_.b.arrow.p, k_.c.arrow.p), v.m, v.w};
}

}  // namespace pita
