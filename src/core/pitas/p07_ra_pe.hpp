// P7:Ra-Pe (Sec. 3.3, PITA Eq. 35-36, appendix E): every point of the moving
// zero-turn arrow obeys x'' = K (x - f) for one complex K and fixed point f
// (radial perseverance). On the normalised time tau = 2 u - 1 (u = knot_warp)
// every point of the arrow moves as
//   x(tau) = x_b + (x_a + x_c - 2 x_b)/2 Q(tau) + (x_c - x_a)/2 S(tau),
// the parabola with tau^2 -> Q and tau -> S (perseverant.hpp), which is finite
// as f goes to infinity. The fixed point is f = p_b + (2 p_b - p_a - p_c) /
// (2 (kappa - 1)) (PITA Eq. E.12). Windings are ignored (zero-turn arrows).
#pragma once

#include <optional>

#include "core/keyframe.hpp"
#include "core/perseverant.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

class RaPe final : public Motion {
 public:
  explicit RaPe(const KeyframeTriple& k);
  Arrow at(double t) const override;

 private:
  KeyframeTriple k_;
  Perseverant pe_;

 public:
  // f of PITA Eq. E.12, or nothing when P7 degenerates to P1's parabola (kappa = 1).
  std::optional<Point> fixed_point() const;
  std::optional<Point> global_fixed_point() const override { return fixed_point(); }
};

}  // namespace pita
