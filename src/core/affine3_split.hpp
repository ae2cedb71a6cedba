// The split of a 3x3 linear part (SAM paper appendix A.6; docs/paper-notes.md
// N58): one real eigenvalue lambda and an orthonormal right-handed basis
// Q = [u, q2, q3] with L u ~ lambda u, the first step of the real Schur form,
// so that Q^T L Q = [[lambda, w^T], [0, M]] up to the residual of u. Internal
// to EAR in 3D (core/affine_power_of_space.cpp); the eigenvalues themselves are
// pita::eigenvalues (core/affine_power_of_space.hpp).
#pragma once

#include <array>
#include <cmath>
#include <complex>

#include <Eigen/Core>

namespace pita::detail {

// |z| without hypot (its overflow care is not needed for eigenvalues of a
// finite 3x3, and it is slow).
inline double modulus(std::complex<double> z) { return std::sqrt(z.real() * z.real() + z.imag() * z.imag()); }

// Whether the three computed eigenvalues (pita::eigenvalues) are one triple
// eigenvalue: rounding may have made a complex pair of it, or three distinct reals.
bool triple_cluster(const std::array<std::complex<double>, 3>& values);

// The eigenvalue to split off: the real one of a complex pair; the positive
// one beside two negative ones; else the most isolated (a triple cluster
// gives tr/3, their mean, exact where each root is only good to the cube
// root of rounding).
double split_guess(const Eigen::Matrix3d& L, const std::array<std::complex<double>, 3>& values);

struct Split {
  double lambda_guess = 0.0;  // the eigenvalue split off, as the cubic gives it
  Eigen::Matrix3d Q;          // [u, q2, q3]
};

// L's split at split_guess; u's largest component is positive (which fixes
// the half turn).
Split split(const Eigen::Matrix3d& L);

// Q^T L Q; with complex eigenvalues of the plane block, (q2, q3) are first
// turned (Q updated) so that its diagonal entries are equal, the standardised
// block of the real Schur form (LAPACK's dlanv2).
Eigen::Matrix3d standardised_split(const Eigen::Matrix3d& L, Eigen::Matrix3d& Q);

}  // namespace pita::detail
