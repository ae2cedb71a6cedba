// P3:Pa-LP (Sec. 3.1): parabolic point (PITA Eq. 11), log-polar vector (-LP).
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

class PaLp final : public Motion {
 public:
  explicit PaLp(const KeyframeTriple& k);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
};

}  // namespace pita
