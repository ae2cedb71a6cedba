#include "core/pitas/p01_pa_ca.hpp"

#include "core/point_motions.hpp"
#include "core/vector_motions.hpp"

namespace pita {

PaCa::PaCa(const KeyframeTriple& k) : k_(k) {}

Arrow PaCa::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  const Point p = parabolic_point(l, k_.a.arrow.p, k_.b.arrow.p, k_.c.arrow.p);
  return arrow_from_vector(p, cartesian_vector(l, k_.a.arrow, k_.b.arrow, k_.c.arrow));
}

}  // namespace pita
