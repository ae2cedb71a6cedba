// A pose PITA past three poses: the blend chain of the arrow tracks
// (docs/paper-notes.md N33) over affine poses (N79). On the span
// [t_i, t_{i+1}]
//   D(t) = M(X(t), Y(t), s) = (Y(t) o X(t)^-1)^s o X(t),   s = (t - t_i)/(t_{i+1} - t_i),
// with X the pose PITA through poses i-1, i, i+1, Y the one through i, i+1,
// i+2 and M the steady affine morph of morph_and_transport.hpp (PITA Eq. 20
// with the SAM's power). The first and last spans, and times outside the
// knots, use the one triple they have; three poses are the pose PITA itself.
// Both triples pass through poses i and i+1 at their knots, where
// Y o X^-1 = I: D is C1 at every interior knot, as the arrow blend chain.
#pragma once

#include <span>
#include <vector>

#include "core/pose_pitas/pose_pita.hpp"

namespace pita {

template <class Pose>
class PoseBlendChain {
 public:
  // `poses`: n >= 3, knots strictly increasing; `method` a pose PITA. Throws
  // NoPosePitaPower as each triple's PITA does (first() then counts from
  // the first of all the poses).
  PoseBlendChain(PoseMethod method, std::span<const TimedPoseOf<Pose>> poses);
  // Throws NoPosePitaPower (naming t) when a triple refuses at t, or when
  // X(t) and Y(t) have no SAM between them.
  Pose at(double t) const;

 private:
  std::vector<double> knots_;
  std::vector<PosePita<Pose>> triples_;  // triples_[j] through poses j, j+1, j+2
};

extern template class PoseBlendChain<Affine2>;
extern template class PoseBlendChain<Affine3>;

}  // namespace pita
