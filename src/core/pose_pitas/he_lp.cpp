#include "core/pose_pitas/he_lp.hpp"

#include "core/lagrange_weights.hpp"

namespace pita {

template <class Pose>
PoseHeLp<Pose>::PoseHeLp(const PoseTriple<Pose>& k)
    : k_(k), centroid_((k[0].pose.b + k[1].pose.b + k[2].pose.b) / 3.0) {
  // (1) translate by -g (appendix C; docs/paper-notes.md N78)
  for (std::size_t i = 0; i < 3; ++i) log_[i] = pose_log(Pose{k[i].pose.L, k[i].pose.b - centroid_}, i);
}

template <class Pose>
Pose PoseHeLp<Pose>::at(double t) const {
  const LagrangeWeights l = lagrange_weights(k_[0].t, k_[1].t, k_[2].t, t);
  // (2) H(t) = exp(x log A' + y log B' + z log C')   (PITA Eq. 33)
  const Pose blend{lagrange(l, log_[0].L, log_[1].L, log_[2].L).eval(),
                   lagrange(l, log_[0].b, log_[1].b, log_[2].b).eval()};
  // (3) translate back by +g
  Pose d = exp(blend);
  d.b += centroid_;
  return d;
}

template class PoseHeLp<Affine2>;
template class PoseHeLp<Affine3>;

}  // namespace pita
