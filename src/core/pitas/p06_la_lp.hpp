// P6:La-LP (Sec. 3.2, PITA Eq. 34 as docs/paper-notes.md N4 reads it): the steady
// average of
//   L = T1(a, A, b, B, c, C, t) = T_{B->C}^{z} . M(A, B, y + z),
//   R = T1(c, C, b, B, a, A, t) = T_{B->A}^{x} . M(C, B, x + y),
// with the Lagrange weights x, y, z of PITA Eq. 10.
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"
#include "core/twirl.hpp"

namespace pita {

class LaLp final : public Motion {
 public:
  explicit LaLp(const KeyframeTriple& k);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  Twirl a_to_b_, b_to_c_, c_to_b_, b_to_a_;
};

}  // namespace pita
