// The quad strip of a pattern (Sec. 7.2-7.3, Fig. 13): the frames D(t_0) ...
// D(t_{n-1}) define quads (p_i, q_i, q_{i+1}, p_{i+1}). Its (along, across)
// parameterisation maps u in [0, n - 1] and v in [0, 1] bilinearly inside
// quad floor(u): v = 0 on the p side, v = 1 on the q side.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/arrow.hpp"

namespace pita::render {

class QuadStrip {
 public:
  // At least two frames.
  explicit QuadStrip(std::span<const Arrow> frames);

  int quad_count() const { return static_cast<int>(p_.size()) - 1; }
  // Corners of quad i in the order p_i, q_i, q_{i+1}, p_{i+1}.
  std::array<Point, 4> quad(int i) const;
  // The point at (u, v); u is clamped to [0, n - 1].
  Point at(double u, double v) const;

 private:
  std::vector<Point> p_, q_;
};

}  // namespace pita::render
