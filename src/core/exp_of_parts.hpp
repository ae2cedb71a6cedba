// e^{tC} for a 2x2 C = x I + M, M traceless with M^2 = gamma I (SAM paper
// SAM Eq. 11, written with the discriminant gamma of C so that it stays real):
//   e^{tC} = e^{tx} (cosh(t sqrt gamma) I + t sinh(t sqrt gamma)/(t sqrt gamma) M),
// exact as gamma -> 0 (Jordan blocks), and through the spectral projectors
// when the real eigenvalues are far apart (cosh and sinh would cancel in the
// small eigenvalue's direction). Internal to EAR (core/affine_power.cpp).
#pragma once

#include <Eigen/Core>

namespace pita::detail {

// e^{tC}, C = x I + M.
Eigen::Matrix2d exp_of_parts(double x, const Eigen::Matrix2d& M, double gamma, double t);

// e^{tC} - I, exact for small t (expm1 in each term).
Eigen::Matrix2d exp_of_parts_minus_identity(double x, const Eigen::Matrix2d& M, double gamma, double t);

}  // namespace pita::detail
