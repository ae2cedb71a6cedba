// Real powers of 3D affinities: EAR in space, the SAM paper's appendix A.6
// (docs/paper-notes.md N58).
//
// A.6 splits L into a scaling by a real positive eigenvalue lambda along its
// eigenvector u and a 2D problem on the rest, solved by the 2D EAR
// (affine_power.hpp). We make the split with an orthonormal, right-handed
// basis Q = [u, q2, q3] (one step of the real Schur form), in which the
// homogeneous matrix of A is block upper triangular:
//
//     Q^T A Q = [[lambda, w^T, beta],     lambda: the scaling along u
//                [0,      M,   c   ],     [M | c]: a 2D affinity (2D EAR)
//                [0,      0,   1   ]]     w: how the plane leans on u
//
// and every primary function f of it (f = z^t for A^t, f = ln for log A) is
// block triangular too, with the divided differences of f coupling the
// blocks (Parlett's recurrence):
//   f(Q^T A Q) = [[f(lambda), w^T f[lambda, M], f[lambda, 1] beta + w^T f[lambda, M, 1] c],
//                 [0,         f(M),             f[M, 1] c                                 ],
//                 [0,         0,                f(1)                                      ]].
// Each divided difference is a 2D EAR quantity or a scalar:
//   (z^t)[M, 1] c   = g_t(M) c, g_t(z) = (z^t - 1)/(z - 1): the translation of [M | c]^t;
//   (z^t)[lambda, M] = lambda^(t-1) g_t(M / lambda): the same on [M / lambda | .];
//   ln[M, 1] c      = l(M) c, l(z) = ln z/(z - 1), and ln[lambda, M] = l(M / lambda) / lambda;
//   f[lambda, M, 1] = (f[lambda, M] - f[M, 1])/(lambda - 1), or
//                   = (f[lambda, 1] I - f[M, 1]) (lambda I - M)^-1,
// whichever denominator is farther from zero; when both are near zero (every
// eigenvalue of L within 1/4 of 1: the identity, translations, shears, Jordan
// blocks at 1) the translation is a binomial series in L - I instead, as in
// 2D. This is A.6's case analysis in one formula: with 1 not an eigenvalue
// it is SAM Eq. 9 about the fixed point; with lambda = 1 (the kernel N of L - I)
// the corner is t beta, the constant-velocity translation along N of A.6,
// and [M | c] is the 2D SAM on the rest; double and triple eigenvalues and
// Jordan blocks are where the 2D EAR's own exact limits take over.
//
// With complex eigenvalues on the plane, (q2, q3) is turned so that M's
// diagonal entries are equal (the standardised Schur block): the 2D EAR's
// discriminant is then free of cancellation.
//
// Which eigenvalue: the real one when the other two are complex; of three
// real positive ones the one farthest from the other two (the Sylvester
// coupling is then best conditioned); with two negative ones the positive one
// (the negative pair must be a rotation by pi with uniform scale, S2, taken
// as the rotation by +pi about u, u's largest component positive: N58).
// Thresholds: limits.hpp ("EAR in 3D").
#pragma once

#include <array>
#include <complex>
#include <optional>

#include <Eigen/Core>

#include "core/affine3.hpp"
#include "core/affine_power.hpp"

namespace pita {

// The eigenvalues of L (closed-form cubic, approximate: good to about
// 1e-16 |L| for simple ones, to the cube root of that for a triple one), the
// real ones first, in decreasing order, then a complex pair (+ imaginary part
// first).
std::array<std::complex<double>, 3> eigenvalues(const Eigen::Matrix3d& L);

// A's fixed point q = L q + b (A.6, PITA Eq. 21); nullopt when 1 is an eigenvalue
// of L (within limits::kUnitEigenvalue: no unique fixed point).
std::optional<Eigen::Vector3d> fixed_point(const Affine3& A);

// The real powers A^t of one 3D affinity (EAR, A.6), with the verbs of the
// 2D EAR (affine_power.hpp). The constructor makes the split and the 2D EARs
// once; at(t) is then a few 2D powers.
template <>
class AffinePowers<Affine3> {
 public:
  // Throws NoRealLogarithm (case G3) when L has no real log (a negative
  // eigenvalue of odd multiplicity or a negative Jordan block, Culver, Sec.
  // 5.1), det L <= 0, or a non-finite entry; what() lists the eigenvalues.
  explicit AffinePowers(const Affine3& A);

  // A^t: at(0) = identity, at(1) = A, at(s) o at(t) = at(s + t). A
  // non-finite t gives a non-finite affinity (NaN).
  Affine3 at(double t) const;

  // The powers of [L | b], A's linear part with another translation b: the
  // same as AffinePowers(Affine3{L, b}) without redoing the split and the
  // 2D EARs. Throws NoRealLogarithm for a non-finite b, as the constructor does.
  AffinePowers with_translation(const Eigen::Vector3d& b) const;

  const Affine3& affinity() const { return A_; }

  // The homogeneous log of A as {log L, v} ([[log L, v], [0, 0]]): the
  // SAM's constant velocity field x -> log(L) x + v. Computed on demand (at()
  // does not need it). The split's log, then Newton steps in extended
  // precision where exp of it misses A by more than 1e-13 (N58).
  Affine3 log() const;

  // d/dt A^t = log A A^t, as (dL/dt, db/dt) = (log(L) L^t, log(L) b_t + v),
  // b_t the translation of A^t. Takes log() each call (about 2 us, more where
  // its Newton steps are needed, N58); at() never does.
  Affine3 velocity(double t) const;

  // The log by the split alone (A.6), before log()'s refinement (for tests
  // and the paper note).
  Affine3 split_log() const;

  // The split (for tests and the paper note): the eigenvalue lambda, the
  // right-handed orthonormal basis Q = [u, q2, q3].
  double split_eigenvalue() const { return lambda_; }
  const Eigen::Matrix3d& basis() const { return Q_; }

 private:
  // How the corner f[lambda, M, 1] (the translation along u) is computed.
  enum class Corner { unit_series, over_lambda_minus_one, over_lambda_minus_M };

  void set_translation(const Eigen::Vector3d& b);  // A_.b, and beta_ and c_ from it
  Affine3 at_small(double t) const;
  Eigen::Vector3d unit_series(double t) const;         // g_t(L) b, |t| <= kUnitSeriesMaxTime
  Eigen::Matrix3d unit_series_linear(double t) const;  // L^t by the binomial series, |t| <= kUnitSeriesMaxTime

  Affine3 A_;
  Eigen::Matrix3d Q_;
  double lambda_ = 1.0;
  double log_lambda_ = 0.0;
  Eigen::Vector2d w_, c_, lean_solve_;  // lean_solve_ = (lambda I - M)^-1 c
  double beta_ = 0.0;
  std::optional<AffinePowers<Affine2>> plane_;     // [M | c]
  std::optional<AffinePowers<Affine2>> relative_;  // [M^T / lambda | 0]
  Corner corner_ = Corner::over_lambda_minus_one;
  Eigen::Matrix2d M_;               // the plane block
  bool lean_by_sylvester_ = false;  // log(): the lean row by Sylvester (N58)
  // Near the identity with an ill-determined split: L^t by the binomial series (N80).
  bool linear_by_series_ = false;
};

AffinePowers(const Affine3&)->AffinePowers<Affine3>;

// A^t (builds AffinePowers; use the class for many t).
Affine3 affine_power(const Affine3& A, double t);

// ------------------------------------------------------------ shared verbs
// pow, log, exp as for Affine2 (affine_power.hpp). A generator (the velocity
// field x -> C x + v) is written as an affinity-shaped pair {C, v}.

// A^t by EAR; throws NoRealLogarithm when there is none.
inline Affine3 pow(const Affine3& A, double t) { return affine_power(A, t); }

// The homogeneous log of A, {log L, v}; throws NoRealLogarithm.
Affine3 log(const Affine3& A);

// exp of a generator {C, v}: the exponential of [[C, v], [0, 0]] (Eigen's
// scaling and squaring Pade). exp(t log A) = A^t.
Affine3 exp(const Affine3& generator);

}  // namespace pita
