// Independent PITAs (Sec. 3.1, Fig. 7): a point motion for D(t).p combined
// with a vector motion for D(t).w, chosen independently. P1 (Pa-Ca), P2
// (LS-Po) and P3 (Pa-LP) are three of the six combinations and have their own
// classes; this class builds any of them, and the registry offers the other
// three (Pa-Po, LS-Ca, LS-LP) so that Fig. 7 can be reproduced.
#pragma once

#include "core/keyframe.hpp"
#include "core/pitas/motion.hpp"
#include "core/point_motions.hpp"

namespace pita {

enum class PointMotion { parabola, log_spiral };          // Pa- (PITA Eq. 11), LS- (PITA Eq. 26)
enum class VectorMotion { cartesian, polar, log_polar };  // -Ca, -Po, -LP

class IndependentPita final : public Motion {
 public:
  IndependentPita(const KeyframeTriple& k, PointMotion point, VectorMotion vector);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  PointMotion point_;
  VectorMotion vector_;
  LogSpiral spiral_;  // of the start points (used by LS- only)
};

}  // namespace pita
