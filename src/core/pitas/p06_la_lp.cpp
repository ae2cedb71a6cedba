#include "core/pitas/p06_la_lp.hpp"

#include "core/lagrange_weights.hpp"
#include "core/steady_morph.hpp"

namespace pita {

LaLp::LaLp(const KeyframeTriple& k)
    : k_(k),
      a_to_b_(twirl_between(k.a.arrow, k.b.arrow)),
      b_to_c_(twirl_between(k.b.arrow, k.c.arrow)),
      c_to_b_(twirl_between(k.c.arrow, k.b.arrow)),
      b_to_a_(twirl_between(k.b.arrow, k.a.arrow)) {}

Arrow LaLp::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  // L = T_{B->C}^z . M(A, B, y + z)   (PITA Eq. 34)
  const Arrow left = apply_power(b_to_c_, l.z, apply_power(a_to_b_, l.y + l.z, k_.a.arrow));
  // R = T_{B->A}^x . M(C, B, x + y)   (PITA Eq. 34 with knots c, b, a)
  const Arrow right = apply_power(b_to_a_, l.x, apply_power(c_to_b_, l.x + l.y, k_.c.arrow));
  return steady_average(left, right);
}

}  // namespace pita
