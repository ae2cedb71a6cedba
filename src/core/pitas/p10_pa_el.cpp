#include "core/pitas/p10_pa_el.hpp"

#include "core/point_motions.hpp"

namespace pita {

PaEl::PaEl(const KeyframeTriple& k) : k_(k) {}

Arrow PaEl::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_.a.t, k_.b.t, k_.c.t, t);
  const Arrow& A = k_.a.arrow;
  const Arrow& B = k_.b.arrow;
  const Arrow& C = k_.c.arrow;
  // exp(x log L(A) + y log L(B) + z log L(C)) with principal logs (PITA Eq. A.3, A.5).
  const double log_m = lagrange(l, std::log(A.m), std::log(B.m), std::log(C.m));
  const double angle = lagrange(l, principal_angle(A.w), principal_angle(B.w), principal_angle(C.w));
  return {parabolic_point(l, A.p, B.p, C.p), std::exp(log_m), angle};
}

}  // namespace pita
