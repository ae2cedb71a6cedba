#include "core/pose_pitas/la_lp.hpp"

#include "core/lagrange_weights.hpp"

namespace pita {

template <class Pose>
PoseLaLp<Pose>::PoseLaLp(const PoseTriple<Pose>& k)
    : k_(k),
      a_to_b_(neighbours_morph(k[0].pose, k[1].pose, 0)),
      b_to_c_(neighbours_morph(k[1].pose, k[2].pose, 1)),
      c_to_b_(neighbours_morph(k[2].pose, k[1].pose, 1)),
      b_to_a_(neighbours_morph(k[1].pose, k[0].pose, 0)) {}

template <class Pose>
Pose PoseLaLp<Pose>::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_[0].t, k_[1].t, k_[2].t, t);
  // L = T(M(A, B, y + z), B, C, z)   (PITA Eq. 34)
  const Pose left = transported(b_to_c_, a_to_b_.at(l.y + l.z), l.z);
  // R = T(M(C, B, x + y), B, A, x)   (PITA Eq. 34 with knots c, b, a)
  const Pose right = transported(b_to_a_, c_to_b_.at(l.x + l.y), l.x);
  // D = M(L, R, 1/2), the steady average (N4)
  return formed_morph(left, right, "between L(t) and R(t), which P6 averages", t).at(0.5);
}

template class PoseLaLp<Affine2>;
template class PoseLaLp<Affine3>;

}  // namespace pita
