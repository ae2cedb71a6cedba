// The "bezier-spiral" chain (docs/paper-notes.md N33): the course project's
// Bezier motion. On the span [t_i, t_{i+1}], with S the SMA from keyframe i
// to i + 1 and s = (t - t_i)/(t_{i+1} - t_i), the start point and the end
// point each follow the cubic Bezier curve whose controls are their positions
// in S at s = 0, 1/3, 2/3 and 1, evaluated by de Casteljau's algorithm:
//   p(s) = B(S(0).p, S(1/3).p, S(2/3).p, S(1).p; s), likewise q(s).
// The curve passes the span's ends only (not S(1/3), S(2/3)). An arrow from
// p to q has no winding of its own; pita takes the angle of q - p on the
// branch nearest the SMA's winding at the same s, so the span turns as many
// times as its SMA does and every keyframe is reached with its own winding.
// Outside the knots the first and last span's cubics are extrapolated.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "core/chains/chain.hpp"

namespace pita {

class BezierSpiralChain final : public Motion {
 public:
  BezierSpiralChain(std::span<const Keyframe> keyframes, const WindowMotion& sma);
  Arrow at(double t) const override;

 private:
  struct Span {
    std::unique_ptr<Motion> sma;
    std::array<Point, 4> p, q;  // Bezier controls of the start and end points
  };
  std::vector<double> knots_;
  std::vector<Span> spans_;
};

// de Casteljau's evaluation of the cubic Bezier curve with controls c at any
// real s (extrapolates outside [0, 1]).
Point de_casteljau(const std::array<Point, 4>& c, double s);

}  // namespace pita
