// P5S:Hs-LP, our similarity-invariant variant of P5 (docs/paper-notes.md N7):
// the same blend of homogeneous logs, done in the frame of the steady average
// F = M(A, C) instead of about the centroid. Each keyframe is expressed in F's
// frame (F^{-1} . A), blended as P5 does (principal angles), and mapped back by
// F. Because F is carried along by any similarity of the keyframes (including
// its winding), PITA Eq. 40 holds exactly, for every rotation.
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

class HsLp final : public Motion {
 public:
  explicit HsLp(const KeyframeTriple& k);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  Arrow frame_;  // F = M(A, C)
  Complex log_[3];
  Complex translation_log_[3];
};

}  // namespace pita
