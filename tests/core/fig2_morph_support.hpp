// Helpers shared by the tests of the morphs of the SAM paper's Fig. 2
// (rARAP, ASAP, TSB): poses, similarities, finite differences.
#pragma once

#include <array>
#include <cmath>
#include <complex>

#include "core/affine2.hpp"
#include "pose_test_support.hpp"

namespace pita::test {

// The poses of scenes/sam-fig02-linear-and-sam.json (the unit triangle onto
// the scene's triangles) and a second, generic pair.
inline const Affine2 kFig2From = pose(2.2, 0.6, 0.3, 1.6, 0.0, 0.0);
inline const Affine2 kFig2To = pose(0.7, -1.6, 2.4, 1.1, 6.5, 0.5);
inline const Affine2 kOtherFrom = pose(1.0, 0.4, -0.2, 0.8, -1.0, 2.0);
inline const Affine2 kOtherTo = pose(-0.9, -1.3, 1.7, -0.4, 3.0, -2.5);
inline const std::array<Point, 3> kUnitTriangle{Point{0.0, 0.0}, Point{1.0, 0.0}, Point{0.0, 1.0}};

// A similarity: scale m, turn w, then translate by (x, y).
inline Affine2 similarity(double m, double w, double x, double y) {
  return pose(m * std::cos(w), -m * std::sin(w), m * std::sin(w), m * std::cos(w), x, y);
}

// The central difference (f(u + h) - f(u - h)) / 2h of a pose-valued motion.
template <typename Motion>
Affine2 central_difference(const Motion& motion, double u, double h = 1e-5) {
  const Affine2 p = motion.at(u + h), m = motion.at(u - h);
  return {(p.L - m.L) / (2.0 * h), (p.b - m.b) / (2.0 * h)};
}

// The steady motion of point x about fixed point f by lambda^u, lambda = m e^{iw}:
// the log spiral f + e^{u (ln m + i w)} (x - f) (PITA Eq. 5, 8).
inline Point on_spiral(Point f, Complex log_lambda, double u, Point x) {
  return f + std::exp(u * log_lambda) * (x - f);
}

// The fixed point of the similarity z -> lambda (z - a) + a' (a != fixed):
// f = (a' - lambda a) / (1 - lambda) (reading notes item 1, with a' = image of a).
inline Point spiral_centre(Complex lambda, Point a, Point image) { return (image - lambda * a) / (1.0 - lambda); }

}  // namespace pita::test
