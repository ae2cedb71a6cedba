// The Persistent Affine Motion (PAM, "UAM" in Muthumanickam's thesis [7]):
// the motion of a triangle through three timed affinities (Sec. 3.3, Eq.
// 37-39, appendix F). P8 (pitas/p08_lo_pe.hpp) is PAM restricted to
// similarities and written in complex numbers; this general form is its
// independent oracle and shows the affine invariance of PITA Eq. 43 (Sec. 4.10).
//
// A point attached to the moving triangle is p(t) = U(t) p0 (PITA Eq. 37); its
// acceleration U''(t) p0 (PITA Eq. 38) is constant in the moving frame:
//     U'' = U o E,  E = [[M, g], [0, 0]] constant            (PITA Eq. 39)
// (homogeneous 3x3 matrices). Splitting U = [[Lin, b], [0, 1]] gives the
// linear system Lin'' = Lin M (the pairs of entries of PITA Eq. F.1, solved in
// appendix F by the matrix exponential of PITA Eq. F.2) and b'' = Lin g.
//
// Like P8, PAM runs on the normalised time tau = 2 knot_warp(a, b, c, t) - 1,
// so tau = -1, 0, 1 at the knots (the paper's U(0), U(1/2), U(1)). With
//     K = L_B^-1 (L_A + L_C) / 2,   cosh(sqrt M) = K,   i.e. M = acosh(K)^2,
// the boundary-value problem U(-1) = A, U(0) = B, U(1) = C is solved by
//     Lin(tau) = L_B C(tau) + (L_C - L_A)/2 S(tau),
//     b(tau)   = b_B + (b_C - b_A)/2 tau
//                + 1/2 L_B Q(tau) w + 1/4 (L_C - L_A) R(tau) w,
//     w = L_B^-1 (b_A + b_C - 2 b_B),
//     M = acosh(K)^2,   g = 1/2 M (K - I)^-1 w,
// where C, S, Q, R are the matrix functions of K of the scalar functions
// (k = acosh kappa, so kappa = cosh k)
//     C = cosh(k tau),  S = sinh(k tau) / sinh k,
//     Q = (C - 1) / (kappa - 1),  R = (S - tau) / (kappa - 1),
// the same four functions as the -Pe machinery of P7/P8 (perseverant.hpp),
// all commuting with K. Q and R are those of b = Lin h + (affine in tau) with
// h = (L_A + L_C - 2 L_B)^-1 (b_A + b_C - 2 b_B) = M^-1 g, rewritten so that
// they stay finite when L_A + L_C - 2 L_B is singular (K has the eigenvalue 1;
// e.g. three pure translations, whose PAM is a parabola): Q -> tau^2 and
// R -> tau (tau^2 - 1)/3 as kappa -> 1, the cubic of P8 (docs/paper-notes.md N13).
//
// Existence. The real M = acosh(K)^2 exists and is unique (principal acosh,
// the branch of P8) unless K has a real eigenvalue <= -1: at -1 sinh k = 0 and
// there is no solution; below -1 (the branch cut where P8 pops) no real M
// exists for distinct eigenvalues and it is not unique for a double one. The
// constructor then throws MotionDomainError, as it does when L_B is singular.
// For similarities K has the eigenvalues kappa and conj(kappa) of P8, so PAM
// refuses exactly P8's cut, which P8 resolves by taking its upper side.
#pragma once

#include <Eigen/Core>

#include "core/affine2.hpp"

namespace pita {

class PersistentAffineMotion {
 public:
  // The affinities A, B, C at the distinct knots a, b, c (a < b < c for the
  // knot warp to be monotone). Throws MotionDomainError (see above).
  PersistentAffineMotion(double a, const Affine2& A, double b, const Affine2& B, double c, const Affine2& C);

  // U(t); values outside [a, c] extrapolate (Sec. 7.5).
  Affine2 at(double t) const;

  // The constant E of PITA Eq. 39 in normalised time tau, as the homogeneous matrix
  // [[M, g], [0, 0]] (an element of the affine Lie algebra, not an affinity).
  Eigen::Matrix3d local_acceleration() const;

 private:
  double a_, b_, c_;               // knots
  Affine2 middle_;                 // B = U(0)
  Eigen::Matrix2d half_L_change_;  // (L_C - L_A)/2
  Eigen::Vector2d half_b_change_;  // (b_C - b_A)/2
  Eigen::Vector2d w_;              // L_B^-1 (b_A + b_C - 2 b_B)
  // K = m I + N with N traceless, N^2 = s2 I (Cayley-Hamilton): the
  // eigenvalues of K are m +- sqrt(s2), complex conjugate when s2 < 0.
  Eigen::Matrix2d N_;
  double m_ = 0.0;
  double s2_ = 0.0;
};

}  // namespace pita
