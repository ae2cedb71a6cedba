#include "render/strip.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pita::render {

QuadStrip::QuadStrip(std::span<const Arrow> frames) {
  if (frames.size() < 2) throw std::invalid_argument("a quad strip needs at least two frames");
  for (const Arrow& frame : frames) {
    p_.push_back(frame.p);
    q_.push_back(frame.q());
  }
}

std::array<Point, 4> QuadStrip::quad(int i) const {
  const auto k = static_cast<std::size_t>(i);
  return {p_[k], q_[k], q_[k + 1], p_[k + 1]};
}

Point QuadStrip::at(double u, double v) const {
  u = std::clamp(u, 0.0, static_cast<double>(quad_count()));
  const int i = std::min(static_cast<int>(std::floor(u)), quad_count() - 1);
  const double f = u - i;
  const auto k = static_cast<std::size_t>(i);
  const Point near = (1.0 - v) * p_[k] + v * q_[k];
  const Point far = (1.0 - v) * p_[k + 1] + v * q_[k + 1];
  return (1.0 - f) * near + f * far;
}

}  // namespace pita::render
