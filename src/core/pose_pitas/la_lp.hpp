// P6:La-LP over affine poses of the plane or of space (docs/paper-notes.md
// N75): PITA Eq. 34 as docs/paper-notes.md N4 reads it, with the steady morph
// M and transport T of morph_and_transport.hpp:
//   L = T(M(A, B, y + z), B, C, z),   R = T(M(C, B, x + y), B, A, x),
//   D = M(L, R, 1/2),
// x, y, z the Lagrange weights of PITA Eq. 10. On similarity poses whose
// neighbours turn by less than pi it is the arrow LaLp (core/pitas/p06_la_lp.hpp).
#pragma once

#include "core/pose_pitas/morph_and_transport.hpp"

namespace pita {

template <class Pose>
class PoseLaLp {
 public:
  // Throws NoPosePitaPower when A, B or B, C have no SAM.
  explicit PoseLaLp(const PoseTriple<Pose>& k);
  // Throws NoPosePitaPower (naming t) when L(t), R(t) have no SAM.
  Pose at(double t) const;

 private:
  PoseTriple<Pose> k_;
  SteadyAffineMorph<Pose> a_to_b_, b_to_c_, c_to_b_, b_to_a_;
};

extern template class PoseLaLp<Affine2>;
extern template class PoseLaLp<Affine3>;

}  // namespace pita
