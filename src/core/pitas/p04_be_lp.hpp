// P4:Be-LP (Sec. 3.2, PITA Eq. 27-32): two Bezier SMAs joined at B, with the
// control arrows of docs/paper-notes.md N3:
//   L = T_{C->B}^{1/4} . M(A, B, 3/4),   R = T_{A->B}^{1/4} . M(C, B, 3/4),
// so that B = M(L, R) and the motion is C1 at t = b. The Bezier parameter is
// u = knot_warp(a, b, c, t) (knot_warp.hpp): for even knots u = (t-a)/(c-a) as
// in the paper; for uneven knots b only warps time (P4 is not knot-controlled).
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"
#include "core/twirl.hpp"

namespace pita {

class BeLp final : public Motion {
 public:
  explicit BeLp(const KeyframeTriple& k);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  Arrow left_control_;   // L
  Arrow right_control_;  // R
  Twirl a_to_l_, l_to_b_, b_to_r_, r_to_c_;

 public:
  const Arrow& left_control() const { return left_control_; }
  const Arrow& right_control() const { return right_control_; }
};

}  // namespace pita
