// P2:LS-Po (Sec. 3.1): log-spiral point (PITA Eq. 26), polar vector (-Po).
// With anchor = midpoint, the log-spiral moves the midpoint p + vector/2 of the
// arrow instead of its start point (the variant drawn in Fig. 1).
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/method_options.hpp"
#include "core/pitas/motion.hpp"
#include "core/point_motions.hpp"

namespace pita {

class LsPo final : public Motion {
 public:
  explicit LsPo(const KeyframeTriple& k, Anchor anchor = Anchor::start);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  Anchor anchor_;
  LogSpiral spiral_;  // through the start points, or the midpoints
};

}  // namespace pita
