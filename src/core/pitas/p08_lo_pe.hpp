// P8:Lo-Pe (Sec. 3.3, PITA Eq. 37-39, appendix F), PAM restricted to
// similarities (docs/paper-notes.md N13): U(tau): z -> a(tau) z + b(tau) with
// U'' = U o E, i.e. a'' = e a and b'' = g a. a is the -Pe vector motion and
// b, the start point, integrates it twice:
//   p(tau) = p_b + (p_c - p_a)/2 tau + (p_a + p_c - 2 p_b)/2 Q(tau)
//            + (p_a + p_c - 2 p_b)(v_c - v_a)/(4 v_b) R(tau),
// which tends to a cubic as kappa -> 1. Every point attached to the arrow has
// an acceleration constant in the moving frame (local perseverance).
// tau = 2 u - 1 with u = knot_warp. Windings are ignored.
#pragma once

#include "core/keyframe.hpp"
#include "core/perseverant.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

class LoPe final : public Motion {
 public:
  explicit LoPe(const KeyframeTriple& k);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  Perseverant pe_;
};

}  // namespace pita
