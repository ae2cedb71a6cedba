// P4:Be-LP over affine poses of the plane or of space (docs/paper-notes.md
// N77): PITA Eq. 27-32 with the control poses of docs/paper-notes.md N3 and
// the steady morph M and transport T of morph_and_transport.hpp:
//   L = T(M(A, B, 3/4), C, B, 1/4),   R = T(M(C, B, 3/4), A, B, 1/4),
// and the two quadratic Bezier SAM arcs (A, L, B) and (B, R, C), each
//   Bezier(P0, P1, P2, s) = M(M(P0, P1, s), M(P1, P2, s), s)      (PITA Eq. 29)
// on u = knot_warp(a, b, c, t) split at 1/2 (PITA Eq. 27, 28). On similarity poses
// whose neighbours turn by less than pi it is the arrow BeLp
// (core/pitas/p04_be_lp.hpp).
#pragma once

#include "core/pose_pitas/morph_and_transport.hpp"

namespace pita {

template <class Pose>
class PoseBeLp {
 public:
  // Throws NoPosePitaPower when A, B or B, C have no SAM, or the control
  // poses have none with their neighbours on the arcs.
  explicit PoseBeLp(const PoseTriple<Pose>& k);
  // Throws NoPosePitaPower (naming t) when the two poses the outer morph of
  // PITA Eq. 29 joins have no SAM.
  Pose at(double t) const;

  const Pose& left_control() const { return left_control_; }
  const Pose& right_control() const { return right_control_; }

 private:
  PoseBeLp(const PoseTriple<Pose>& k, const SteadyAffineMorph<Pose>& a_to_b, const SteadyAffineMorph<Pose>& c_to_b);
  // Bezier(P0, P1, P2, s) of PITA Eq. 29 from the SAMs P0 -> P1 and P1 -> P2.
  static Pose bezier(const SteadyAffineMorph<Pose>& first, const SteadyAffineMorph<Pose>& second, double s, double t);

  PoseTriple<Pose> k_;
  Pose left_control_, right_control_;  // L, R
  SteadyAffineMorph<Pose> a_to_l_, l_to_b_, b_to_r_, r_to_c_;
};

extern template class PoseBeLp<Affine2>;
extern template class PoseBeLp<Affine3>;

}  // namespace pita
