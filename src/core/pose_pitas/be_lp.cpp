#include "core/pose_pitas/be_lp.hpp"

#include "core/knot_warp.hpp"

namespace pita {

template <class Pose>
PoseBeLp<Pose>::PoseBeLp(const PoseTriple<Pose>& k)
    : PoseBeLp(k, neighbours_morph(k[0].pose, k[1].pose, 0), neighbours_morph(k[2].pose, k[1].pose, 1)) {}

// docs/paper-notes.md N3 (the SAM paper's leftControl, its Sec. 5.3):
// L = T(M(A, B, 3/4), C, B, 1/4), R = T(M(C, B, 3/4), A, B, 1/4).
template <class Pose>
PoseBeLp<Pose>::PoseBeLp(const PoseTriple<Pose>& k, const SteadyAffineMorph<Pose>& a_to_b,
                         const SteadyAffineMorph<Pose>& c_to_b)
    : k_(k),
      left_control_(transported(c_to_b, a_to_b.at(0.75), 0.25)),
      right_control_(transported(a_to_b, c_to_b.at(0.75), 0.25)),
      a_to_l_(formed_morph(k[0].pose, left_control_, "between A and the control pose L of P4")),
      l_to_b_(formed_morph(left_control_, k[1].pose, "between the control pose L of P4 and B")),
      b_to_r_(formed_morph(k[1].pose, right_control_, "between B and the control pose R of P4")),
      r_to_c_(formed_morph(right_control_, k[2].pose, "between the control pose R of P4 and C")) {}

// The outer morph of PITA Eq. 29 at s = 0 and 1 is its first or second pose
// whatever the power (docs/paper-notes.md N74): u = 0, 1/2, 1 never refuse.
template <class Pose>
Pose PoseBeLp<Pose>::bezier(const SteadyAffineMorph<Pose>& first, const SteadyAffineMorph<Pose>& second, double s,
                            double t) {
  if (s == 0.0) return first.at(0.0);
  if (s == 1.0) return second.at(1.0);
  return formed_morph(first.at(s), second.at(s), "between the two poses of P4's Bezier arc that its outer morph joins",
                      t)
      .at(s);
}

template <class Pose>
Pose PoseBeLp<Pose>::at(double t) const {
  const double u = knot_warp(k_[0].t, k_[1].t, k_[2].t, t);
  // Bezier(P0, P1, P2, s) = M(M(P0, P1, s), M(P1, P2, s), s)   (PITA Eq. 29)
  if (u <= 0.5) return bezier(a_to_l_, l_to_b_, 2.0 * u, t);  // PITA Eq. 27
  return bezier(b_to_r_, r_to_c_, 2.0 * u - 1.0, t);          // PITA Eq. 28
}

template class PoseBeLp<Affine2>;
template class PoseBeLp<Affine3>;

}  // namespace pita
