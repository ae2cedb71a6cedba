// P10:Pa-EL (appendix B): parabolic point; the vector is the exponential of
// the Lagrange-weighted mean of the logs of the linear parts (PITA Eq. A.3-A.5),
// with principal angles (docs/paper-notes.md N6): m = exp(sum x_i ln m_i),
// w = sum x_i Arg(e^{i w_i}). Equal to P3 when no winding leaves (-pi, pi];
// pops when a keyframe angle crosses +-pi.
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

class PaEl final : public Motion {
 public:
  explicit PaEl(const KeyframeTriple& k);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
};

}  // namespace pita
