#include "analysis/frame_derivatives.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/finite_difference.hpp"
#include "core/instant_center.hpp"

namespace pita::analysis {

namespace {

// The piece [lo, hi] of the time line that holds t: a knot span, or the
// half-line before the first knot or after the last.
struct Piece {
  double lo, hi;
};

Piece piece_of(const std::vector<double>& knots, double t) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (t < knots.front()) return {-kInf, knots.front()};
  if (t > knots.back()) return {knots.back(), kInf};
  const auto after = std::upper_bound(knots.begin(), knots.end() - 1, t);  // first knot > t
  const std::size_t i = std::max<std::size_t>(1, static_cast<std::size_t>(after - knots.begin()));
  return {knots[i - 1], knots[i]};
}

}  // namespace

FrameDerivatives frame_derivatives(const motion::SceneMotion& motion, double t) {
  const std::vector<double>& knots = motion.knots();
  const Piece piece = piece_of(knots, t);
  const double length = std::isfinite(piece.hi - piece.lo) ? piece.hi - piece.lo : knots.back() - knots.front();
  const double h = length / limits::kDerivativeStepsPerSpan;
  std::vector<double> nodes;
  if (t - 2.0 * h >= piece.lo && t + 2.0 * h <= piece.hi) {
    for (int j = -2; j <= 2; ++j) nodes.push_back(t + j * h);
  } else {
    const double start = std::clamp(t - 2.5 * h, piece.lo, piece.hi - 5.0 * h);
    for (int j = 0; j <= 5; ++j) nodes.push_back(start + j * h);
  }
  const std::vector<std::vector<double>> w = fornberg_weights(t, nodes, 2);
  FrameDerivatives d;
  d.t = t;
  const Arrow frame = motion.arrow_at(t);
  d.p = frame.p;
  d.q = frame.q();
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    const Arrow a = motion.arrow_at(nodes[j]);
    // Differences of positions relative to D(t) lose less to rounding.
    const Vector p = a.p - d.p, q = a.q() - d.q;
    d.dp += w[1][j] * p;
    d.dq += w[1][j] * q;
    d.ddp += w[2][j] * p;
    d.ddq += w[2][j] * q;
  }
  return d;
}

std::optional<Point> velocity_center(const FrameDerivatives& d) { return pita::velocity_center(d.p, d.q, d.dp, d.dq); }

std::optional<Point> acceleration_center(const FrameDerivatives& d) {
  return pita::acceleration_center(d.p, d.q, d.ddp, d.ddq);
}

}  // namespace pita::analysis
