#include "core/pose_pitas/ne_lp.hpp"

#include "core/neville_ratios.hpp"

namespace pita {

template <class Pose>
PoseNeLp<Pose>::PoseNeLp(const PoseTriple<Pose>& k)
    : k_(k), a_to_b_(neighbours_morph(k[0].pose, k[1].pose, 0)), b_to_c_(neighbours_morph(k[1].pose, k[2].pose, 1)) {}

template <class Pose>
Pose PoseNeLp<Pose>::at(double t) const {
  const NevilleRatios n = neville_ratios(k_[0].t, k_[1].t, k_[2].t, t);
  const Pose from = a_to_b_.at(n.q), to = b_to_c_.at(n.r);
  // M(X, Y, 0) = X and M(X, Y, 1) = Y whatever the power (at t = a and c:
  // docs/paper-notes.md N74), so the knots never refuse.
  if (n.s == 0.0) return from;
  if (n.s == 1.0) return to;
  // D = M(M(A, B, q), M(B, C, r), s)   (PITA Eq. D.2)
  return formed_morph(from, to, "between M(A, B, q) and M(B, C, r), which P9 morphs", t).at(n.s);
}

template class PoseNeLp<Affine2>;
template class PoseNeLp<Affine3>;

}  // namespace pita
