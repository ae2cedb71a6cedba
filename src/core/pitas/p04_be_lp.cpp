#include "core/pitas/p04_be_lp.hpp"

#include "core/knot_warp.hpp"
#include "core/steady_morph.hpp"
#include "core/steady_transport.hpp"

namespace pita {

BeLp::BeLp(const KeyframeTriple& k) : k_(k) {
  const Arrow& A = k.a.arrow;
  const Arrow& B = k.b.arrow;
  const Arrow& C = k.c.arrow;
  // docs/paper-notes.md N3 (the SAM paper's leftControl, its Sec. 5.3).
  left_control_ = steady_transport(steady_morph(A, B, 0.75), C, B, 0.25);
  right_control_ = steady_transport(steady_morph(C, B, 0.75), A, B, 0.25);
  a_to_l_ = twirl_between(A, left_control_);
  l_to_b_ = twirl_between(left_control_, B);
  b_to_r_ = twirl_between(B, right_control_);
  r_to_c_ = twirl_between(right_control_, C);
}

Arrow BeLp::at(double t) const {
  const double u = knot_warp(k_.a.t, k_.b.t, k_.c.t, t);
  // Bezier(P0, P1, P2, s) = M(M(P0, P1, s), M(P1, P2, s), s) (PITA Eq. 29).
  if (u <= 0.5) {  // PITA Eq. 27
    const double s = 2.0 * u;
    return steady_morph(apply_power(a_to_l_, s, k_.a.arrow), apply_power(l_to_b_, s, left_control_), s);
  }
  const double s = 2.0 * u - 1.0;  // PITA Eq. 28
  return steady_morph(apply_power(b_to_r_, s, k_.b.arrow), apply_power(r_to_c_, s, right_control_), s);
}

}  // namespace pita
