// P5:He-LP over affine poses of the plane or of space (docs/paper-notes.md
// N78): PITA Eq. 33 with appendix C's local origin, as the arrow HeLp
// (core/pitas/p05_he_lp.hpp) does it:
//   (1) translate the poses by -g, g the centroid of their origins (the
//       translations b_A, b_B, b_C: where each pose puts the origin),
//   (2) H(t) = exp(x log A' + y log B' + z log C')                (PITA Eq. 33)
//       with the homogeneous logs of EAR and the Lagrange weights of PITA Eq. 10,
//   (3) translate H(t) back by +g.
// Only the three poses' own logs are taken, once: each pose needs a real log.
#pragma once

#include "core/pose_pitas/morph_and_transport.hpp"

namespace pita {

template <class Pose>
class PoseHeLp {
 public:
  // Throws NoPosePitaPower when a pose, moved by -g, has no real log.
  explicit PoseHeLp(const PoseTriple<Pose>& k);
  // Never throws: the exponential of a real generator is real.
  Pose at(double t) const;

  const typename Pose::Vector& centroid() const { return centroid_; }

 private:
  PoseTriple<Pose> k_;
  typename Pose::Vector centroid_;  // g
  std::array<Pose, 3> log_;         // {log L, v} of each pose moved by -g
};

extern template class PoseHeLp<Affine2>;
extern template class PoseHeLp<Affine3>;

}  // namespace pita
