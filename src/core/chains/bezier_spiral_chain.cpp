#include "core/chains/bezier_spiral_chain.hpp"

#include <cmath>
#include <stdexcept>

#include "core/complex_math.hpp"

namespace pita {

Point de_casteljau(const std::array<Point, 4>& c, double s) {
  const auto lerp = [s](Point a, Point b) { return a + s * (b - a); };
  const Point ab = lerp(c[0], c[1]), bc = lerp(c[1], c[2]), cd = lerp(c[2], c[3]);
  const Point abc = lerp(ab, bc), bcd = lerp(bc, cd);
  return lerp(abc, bcd);
}

BezierSpiralChain::BezierSpiralChain(std::span<const Keyframe> keyframes, const WindowMotion& sma) {
  if (keyframes.size() < 2) throw std::invalid_argument("the bezier-spiral chain needs at least 2 keyframes");
  for (const Keyframe& key : keyframes) knots_.push_back(key.t);
  for (std::size_t i = 0; i + 1 < keyframes.size(); ++i) {
    Span span;
    span.sma = sma(keyframes.subspan(i, 2));
    const double a = knots_[i], b = knots_[i + 1];
    for (int k = 0; k < 4; ++k) {
      // The ends are the keyframes themselves, not the SMA's rounding of them.
      const Arrow frame = k == 0   ? keyframes[i].arrow
                          : k == 3 ? keyframes[i + 1].arrow
                                   : span.sma->at(a + (b - a) * k / 3.0);
      span.p[static_cast<std::size_t>(k)] = frame.p;
      span.q[static_cast<std::size_t>(k)] = frame.q();
    }
    spans_.push_back(std::move(span));
  }
}

Arrow BezierSpiralChain::at(double t) const {
  const std::size_t i = span_of(knots_, t);
  const Span& span = spans_[i];
  const double s = (t - knots_[i]) / (knots_[i + 1] - knots_[i]);
  const Point p = de_casteljau(span.p, s);
  const Point q = de_casteljau(span.q, s);
  const Arrow guide = span.sma->at(t);
  const Vector v = q - p;
  const double m = std::abs(v);
  // The winding: the angle of q - p on the branch nearest the SMA's.
  const double w = m > 0.0 ? guide.w + principal_angle(std::arg(v) - guide.w) : guide.w;
  return {p, m, w};
}

}  // namespace pita
