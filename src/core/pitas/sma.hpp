// SMA as a motion: the timed steady morph M(a, A, b, B, t) (PITA Eq. 21), or its
// non-steady WAM/WHM variants (Sec. 2.7) when a mean other than geometric is
// chosen.
#pragma once

#include "core/keyframe.hpp"
#include "core/mean_kind.hpp"
#include "core/pitas/motion.hpp"
#include "core/twirl.hpp"

namespace pita {

class SteadyMorphMotion final : public Motion {
 public:
  SteadyMorphMotion(const Keyframe& a, const Keyframe& b, MeanKind path_mean = MeanKind::geometric,
                    MeanKind magnitude_mean = MeanKind::geometric);
  Arrow at(double t) const override;

 private:
  Keyframe a_, b_;
  MeanKind path_mean_, magnitude_mean_;
  Twirl twirl_;
};

}  // namespace pita
