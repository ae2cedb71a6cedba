// P9:Ne-LP (appendix D.2, PITA Eq. D.2): the Neville form with steady morphs,
//   D(t) = M(M(A, B, q), M(B, C, r), s)
// with the ratios q, r, s of PITA Eq. 14. With non-geometric means it becomes the
// WAM/WHM variants of Fig. D.36 (mean_morph.hpp).
#pragma once

#include "core/keyframe.hpp"
#include "core/mean_kind.hpp"
#include "core/pitas/motion.hpp"
#include "core/twirl.hpp"

namespace pita {

class NeLp final : public Motion {
 public:
  explicit NeLp(const KeyframeTriple& k, MeanKind path_mean = MeanKind::geometric,
                MeanKind magnitude_mean = MeanKind::geometric);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  MeanKind path_mean_, magnitude_mean_;
  Twirl a_to_b_, b_to_c_;
};

}  // namespace pita
