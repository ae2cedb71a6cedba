// Real powers of 2D affinities: the closed-form EAR algorithm ("Extraction of
// Affinity Roots") of the SAM paper, appendix A (A.1-A.5, Algorithm 1).
//
// An orientation-preserving affinity A: x -> L x + b (core/affine2.hpp) has
// the real powers A^t = e^{t log A} (SAM Eq. 1-2) exactly when L has a real
// logarithm (Sec. 5.1, Culver). With the fixed point q of A (A.1),
//     A^t(p) = L^t (p - q) + q,   L^t = e^{t log L}                  (SAM Eq. 9)
// and log L comes from the case selection of A.5 (Algorithm 1) on
//     r = trace(L)/2,  delta = ((a - d)/2)^2 + b c  (the discriminant; it
//     equals r^2 - det L, but computed from the entries, docs/paper-notes.md N15),
//     N = L - r I (traceless, N^2 = delta I), so L = r I + N:
//  G1  delta < 0, complex eigenvalues r +- i omega:
//        log L = ln(rho) I + (theta/omega) N, rho = sqrt(det L),
//        theta = atan2(omega, r) in (0, pi)                       (SAM Eq. 18, 19)
//  G2  delta >= 0, r > 0, two positive eigenvalues r +- s:
//        log L = ln(rho) I + (atanh(s/r)/s) N                  (SAM Eq. 20, 13-16)
//      including the double eigenvalue (delta = 0: rI or a Jordan block, for
//      which Algorithm 1 has no branch), where the coefficient is 1/r
//  S1  G2 with an eigenvalue 1: the same log, but A has no unique fixed point
//      (a translation, a shear, or a one-directional scaling with a
//      translation, A.4); A^t is computed without q (see limits.hpp)
//  S2  L = -rho I (a rotation by pi with uniform scaling):
//        log L = ln(rho) I + pi J, J the rotation by +pi/2        (A.3, S2)
//  G3  delta >= 0, r < 0, not S2: two negative eigenvalues, or a double one
//      with a single eigenvector: no real logarithm, no SAM (A.3, Sec. 5.1).
// Every threshold is in core/limits.hpp ("EAR").
//
// The SAM from pose B to pose C is A^t o B with A = C o B^-1 (Sec. 2.2,
// steady_affine_morph.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "core/affine2.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

// The cases of appendix A.5.
enum class RootCase { G1, G2, S1, S2, G3 };

// "G1", ... and a few words: "G1 (complex eigenvalues)".
std::string_view name(RootCase kase);
std::string_view description(RootCase kase);

// No real power of the affinity exists: its linear part has no real log (G3),
// or is not orientation preserving (det L <= 0, Sec. 2.1). what() says which,
// with the eigenvalues.
class NoRealLogarithm : public MotionDomainError {
 public:
  NoRealLogarithm(const std::string& reason, RootCase kase) : MotionDomainError(reason), kase_(kase) {}
  // G3 when L has no real log; also G3 for det L <= 0 (no orientation).
  RootCase root_case() const { return kase_; }

 private:
  RootCase kase_;
};

// The case of L (Algorithm 1 with the tolerances of limits.hpp). det L must
// be > 0; a non-finite or non-orientation-preserving L is G3.
RootCase select_case(const Eigen::Matrix2d& L);

// log L by the case's closed form; throws NoRealLogarithm in G3.
Eigen::Matrix2d linear_log(const Eigen::Matrix2d& L);

// e^{tC} of a real 2x2 matrix C (SAM Eq. 11, written with the discriminant of C
// so that it stays real and exact when the eigenvalues of C meet).
Eigen::Matrix2d linear_exp(const Eigen::Matrix2d& C, double t = 1.0);

// L^t = e^{t log L}; throws NoRealLogarithm in G3.
Eigen::Matrix2d linear_power(const Eigen::Matrix2d& L, double t);

// The eigenvalues of L as (real, imaginary) pairs, first the one with the
// larger real part (then the positive imaginary part).
struct Eigenvalues {
  double re1, im1, re2, im2;
};
Eigenvalues eigenvalues(const Eigen::Matrix2d& L);

// A's fixed point q = L q + b (A.1, A.4); nullopt when 1 is an eigenvalue of
// L (S1: no unique fixed point).
std::optional<Eigen::Vector2d> fixed_point(const Affine2& A);

// The real powers A^t of one affinity of the plane or of space: one class
// template, the 2D EAR below and the 3D EAR of appendix A.6 (affine_power_of_space.hpp)
// its two specializations. Both have the same verbs, so that generic code
// (SteadyAffineMorph<Pose>, steady_affine_morph.hpp) calls either:
//   AffinePowers(A)       the analysis of A's linear part, once; throws NoRealLogarithm
//   at(t)                 A^t: at(0) = identity, at(1) = A, at(s) o at(t) = at(s + t)
//   log()                 the homogeneous log {log L, v} of A
//   velocity(t)           d/dt A^t as (dL/dt, db/dt)
//   with_translation(b)   the powers of [L | b], sharing the analysis of L
//   affinity()            A
template <class Pose>
class AffinePowers;

// The 2D EAR. The constructor does the case selection and the log once;
// at(t) is then a few exp/cos calls.
template <>
class AffinePowers<Affine2> {
 public:
  // Throws NoRealLogarithm (G3, or det L <= 0, or non-finite entries).
  explicit AffinePowers(const Affine2& A);

  // A^t (SAM Eq. 9): at(0) = identity, at(1) = A, at(s) o at(t) = at(s + t).
  // A non-finite t gives a non-finite affinity (NaN), as an overflow does.
  Affine2 at(double t) const;

  // The powers of [L | b], A's linear part with another translation b: the
  // same as AffinePowers(Affine2{L, b}) without redoing the analysis of L.
  // Throws NoRealLogarithm for a non-finite b, as the constructor does.
  AffinePowers with_translation(const Eigen::Vector2d& b) const;

  // The power of [L | b], the affinity with A's linear part and another
  // translation b: [L^t | g_t(L) b], g_t(L) = (L^t - I)(L - I)^-1.
  Affine2 power_with_translation(double t, const Eigen::Vector2d& b) const;

  RootCase root_case() const { return case_; }
  const Affine2& affinity() const { return A_; }

  // The homogeneous log {log L, v} of A ([[log L, v], [0, 0]]): the velocity
  // field x -> log(L) x + v of the SAM, the same at every time (Sec. 2.3 (6)).
  Affine2 log() const { return {C_, v_}; }
  const Eigen::Matrix2d& linear_log() const { return C_; }
  Eigen::Vector2d velocity_translation() const { return v_; }
  // The translation of log [L | b] for another translation b: l(L) b with
  // l(lambda) = ln(lambda)/(lambda - 1).
  Eigen::Vector2d log_translation(const Eigen::Vector2d& b) const { return log_ratio_ * b; }

  // d/dt A^t = A^t log A, as (dL/dt, db/dt) = (log(L) L^t, L^t v).
  Affine2 velocity(double t) const;

 private:
  // How g_t(L) = (L^t - I)(L - I)^-1, the translation part of A^t applied to
  // b, is computed (limits.hpp, "EAR").
  enum class Translation { unit_series, fixed_point, eigenvalues };

  Affine2 at_small(double t, const Eigen::Vector2d& b) const;  // |t| <= kUnitSeriesMaxTime, or any t
  Eigen::Matrix2d power_of_linear(double t) const;             // L^t
  Eigen::Matrix2d power_minus_identity(double t) const;        // L^t - I, exact near t = 0
  Eigen::Matrix2d unit_function(double f1, double f2) const;   // f(E) from f(mu1), f(mu2)

  Affine2 A_;
  RootCase case_ = RootCase::G2;
  double c_ = 0.0;      // log L = c I + M,
  Eigen::Matrix2d M_;   // M traceless,
  double gamma_ = 0.0;  // M^2 = gamma I
  Eigen::Matrix2d C_;   // log L
  Eigen::Vector2d v_;   // translation part of log A
  Translation translation_ = Translation::fixed_point;
  Eigen::Matrix2d E_;  // L - I
  double trace_E_ = 0.0, det_E_ = 0.0;
  double mu1_ = 0.0, mu2_ = 0.0;       // the eigenvalues of E (Translation::eigenvalues: real)
  Eigen::Matrix2d inverse_I_minus_L_;  // (I - L)^-1 (Translation::fixed_point)
  Eigen::Matrix2d log_ratio_;          // l(L) = log(L) (L - I)^-1
};

AffinePowers(const Affine2&)->AffinePowers<Affine2>;

// A^t (builds AffinePowers; use the class for many t).
Affine2 affine_power(const Affine2& A, double t);

// ------------------------------------------------------------ shared verbs
// The verbs every value type of the core shares under the same names, so that
// generic code calls any of them: apply, compose, inverse (affine2.hpp), and
// pow, log, exp here. A generator (an element of
// the Lie algebra, the velocity field x -> C x + v) is written as an
// affinity-shaped pair {C, v}, as velocities are.

// A^t by EAR; throws NoRealLogarithm in G3.
inline Affine2 pow(const Affine2& A, double t) { return affine_power(A, t); }

// The homogeneous log of A, {log L, v} (A.2-A.5: the SAM's constant velocity
// field, Sec. 2.3 (6)); throws NoRealLogarithm in G3.
Affine2 log(const Affine2& A);

// exp of a generator {C, v}: [e^C | phi(C) v], phi(C) = sum C^k / (k + 1)!,
// the exponential of the homogeneous matrix [[C, v], [0, 0]]. exp(t log A) = A^t.
Affine2 exp(const Affine2& generator);

}  // namespace pita
