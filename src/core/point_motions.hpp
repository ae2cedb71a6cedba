// The point motions p(t) of the PITAs (Sec. 3.1): the first two letters of a
// mnemonic (Pa-, LS-).
#pragma once

#include "core/arrow.hpp"
#include "core/lagrange_weights.hpp"
#include "core/twirl.hpp"

namespace pita {

// Pa-: the parabolic point motion, the weighted arithmetic mean of the three
// points with the Lagrange weights (PITA Eq. 11). Constant acceleration in the
// global frame (global perseverance).
inline Point parabolic_point(const LagrangeWeights& l, Point pa, Point pb, Point pc) { return lagrange(l, pa, pb, pc); }

// LS-: the log-spiral point motion (PITA Eq. 26 as docs/paper-notes.md N2 reads it):
// p(t) = T_{ab->bc}^{u(t)} . a, with T_{ab->bc} the twirl between the zero-turn
// arrows ab and bc (so T.a = b and T.b = c) and u the quadratic Lagrange time
// map u(a) = 0, u(b) = 1, u(c) = 2, i.e. u = y + 2z. The twirl's angle is the
// principal Arg((c - b)/(b - a)), which is what makes LS- pop when a, b, c are
// collinear with b outside [a, c]. When b nearly coincides with a or c the
// spiral degenerates (limits::kLogSpiralDegenerate) and the parabolic motion is
// used instead.
class LogSpiral {
 public:
  LogSpiral(Point pa, Point pb, Point pc);
  Point at(const LagrangeWeights& l) const;

 private:
  Point pa_, pb_, pc_;
  bool degenerate_;
  Twirl spiral_;  // T_{ab->bc}
};

inline Point log_spiral_point(const LagrangeWeights& l, Point pa, Point pb, Point pc) {
  return LogSpiral(pa, pb, pc).at(l);
}

}  // namespace pita
