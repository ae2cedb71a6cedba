#include "core/arap_decomposition.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/LU>

namespace pita {

Eigen::Matrix2d rotation(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  return R;
}

ArapDecomposition arap_decomposition(const Eigen::Matrix2d& L) {
  if (!L.allFinite() || !(L.determinant() > 0.0)) {
    throw std::invalid_argument(
        "the ARAP decomposition needs an orientation-preserving linear part (det L > 0): ARAP "
        "interpolates no reflection");
  }
  // The 2x2 SVD in closed form, L = R(phi) diag(y1, y2) R(theta): write
  // L = [[E + F, G - H], [G + H, E - F]] (its conformal part E, H and
  // anti-conformal part F, G); then y1,2 = Q +- R with Q = |E + iH|, R = |F + iG|,
  // phi + theta = atan2(H, E) and phi - theta = atan2(G, F). Both factors are
  // rotations by construction (no sign to exchange, Sec. 3.3.2), and y2 > 0
  // because det L = Q^2 - R^2 > 0.
  const double E = 0.5 * (L(0, 0) + L(1, 1)), F = 0.5 * (L(0, 0) - L(1, 1));
  const double G = 0.5 * (L(1, 0) + L(0, 1)), H = 0.5 * (L(1, 0) - L(0, 1));
  const double Q = std::hypot(E, H), R = std::hypot(F, G);
  const double sum = std::atan2(H, E), difference = std::atan2(G, F);
  ArapDecomposition d;
  d.singular = Eigen::Vector2d(Q + R, Q - R);
  d.alpha = 0.5 * (sum + difference);  // R(alpha) = U^T, in (-pi, pi)
  d.beta = 0.5 * (sum - difference);   // R(beta) = V, in (-pi, pi)
  // alpha + beta = atan2(H, E), already in (-pi, pi]: the angle of the polar
  // rotation (L + cof L = 2 [[E, -H], [H, E]]), with no turn to remove.
  // A half turn (L = -s I, H = +-0) is the turn by +pi, also when H is -0.
  d.angle = sum == -std::numbers::pi ? std::numbers::pi : sum;
  const Eigen::Matrix2d B = rotation(-d.beta) * d.singular.asDiagonal() * rotation(d.beta);
  d.stretch = 0.5 * (B + B.transpose());  // symmetric against rounding
  return d;
}

}  // namespace pita
