// The decomposition of a linear part that ARAP [Alexa et al. 2000] animates,
// as the SAM paper restates it (Sec. 3.3.2, docs/paper-notes.md N39):
//     L = U^T Y V                         (the SVD, U and V rotations)
//       = R(alpha) R(beta) (R(-beta) Y R(beta)) = R(alpha + beta) B,
// with R(alpha) = U^T, R(beta) = V, Y = diag(y1, y2), y1 >= y2 > 0, and
// B = R(-beta) Y R(beta) symmetric positive definite. R(alpha + beta) B is the
// polar decomposition of L (B = sqrt(L^T L)), so the rotation and B do not
// depend on how the SVD chose its signs; only the angle's branch does.
//
// Signs and branch: an SVD routine may return reflections (det U = det V = -1
// when det L > 0), which the paper fixes by "exchanging the variables". We
// compute the 2x2 SVD in closed form as a product of two rotations and a
// positive diagonal, so there is nothing to exchange; alpha and beta come
// out in (-pi, pi) and their sum is the angle of the polar rotation, in
// (-pi, pi] (ARAP's recommendation to add or subtract 2 pi is then never
// needed: the turn is the one of at most half a circle). docs/paper-notes.md
// N39. Preconditions: det L > 0 and finite entries (ARAP interpolates no
// reflection), else std::invalid_argument.
#pragma once

#include <Eigen/Core>

namespace pita {

struct ArapDecomposition {
  double alpha = 0.0;  // angle of U^T, (-pi, pi]
  double beta = 0.0;   // angle of V, (-pi, pi]
  double angle = 0.0;  // alpha + beta brought to (-pi, pi]: the rotation R(angle) of L = R B
  Eigen::Vector2d singular = Eigen::Vector2d::Ones();     // y1 >= y2 > 0
  Eigen::Matrix2d stretch = Eigen::Matrix2d::Identity();  // B = R(-beta) Y R(beta)
};

// R(angle): the rotation by `angle` (counter-clockwise).
Eigen::Matrix2d rotation(double angle);

ArapDecomposition arap_decomposition(const Eigen::Matrix2d& L);

}  // namespace pita
