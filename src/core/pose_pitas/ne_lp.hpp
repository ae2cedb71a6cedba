// P9:Ne-LP over affine poses of the plane or of space (docs/paper-notes.md
// N76): the Neville form of PITA appendix D.2 with the steady morph M of
// morph_and_transport.hpp,
//   D = M(M(A, B, q), M(B, C, r), s)                              (PITA Eq. D.2)
// q, r, s the Neville ratios of PITA Eq. 14. On similarity poses whose
// neighbours turn by less than pi it is the arrow NeLp (core/pitas/p09_ne_lp.hpp).
#pragma once

#include "core/pose_pitas/morph_and_transport.hpp"

namespace pita {

template <class Pose>
class PoseNeLp {
 public:
  // Throws NoPosePitaPower when A, B or B, C have no SAM.
  explicit PoseNeLp(const PoseTriple<Pose>& k);
  // Throws NoPosePitaPower (naming t) when M(A, B, q), M(B, C, r) have no SAM.
  Pose at(double t) const;

 private:
  PoseTriple<Pose> k_;
  SteadyAffineMorph<Pose> a_to_b_, b_to_c_;
};

extern template class PoseNeLp<Affine2>;
extern template class PoseNeLp<Affine3>;

}  // namespace pita
