#include "core/pam.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <string>

#include "core/complex_math.hpp"
#include "core/knot_warp.hpp"
#include "core/limits.hpp"
#include "core/pitas/motion.hpp"

namespace pita {

namespace {

// The scalar functions of kappa = cosh k behind U(tau) (pam.hpp):
//   C = cosh(k tau), S = sinh(k tau)/sinh k, Q = (C - 1)/(kappa - 1),
//   R = (S - tau)/(kappa - 1).
// They are even in k, so analytic in kappa off acosh's cut (-inf, -1] and
// real on (-1, inf); at kappa = 1 they take their limits 1, tau, tau^2 and
// tau (tau^2 - 1)/3.
using MotionScalars = std::array<Complex, 4>;  // C, S, Q, R
enum { kC, kS, kQ, kR };

// Taylor series in x = kappa - 1, written here independently of P8's series
// in k^2 (perseverant.cpp). cosh(tau k) = T_tau(kappa) and
// sinh(tau k)/sinh k = U_{tau-1}(kappa) are Chebyshev functions:
//   C = 2F1(-tau, tau; 1/2; -x/2) = sum c_n x^n,
//       c_0 = 1,   c_{n+1} = c_n (tau^2 - n^2) / ((2n + 1)(n + 1)),
//   S = tau 2F1(1 - tau, 1 + tau; 3/2; -x/2) = sum d_n x^n,
//       d_0 = tau, d_{n+1} = d_n (tau^2 - (n + 1)^2) / ((2n + 3)(n + 1)),
// and Q = sum c_{n+1} x^n, R = sum d_{n+1} x^n (drop the constant, divide by x).
// Used while |x| max(1, tau^2) <= limits::kPamSeries: each term is then at
// most a quarter of the one before.
MotionScalars motion_series(Complex x, double tau) {
  const double tau2 = tau * tau;
  Complex C{1.0}, S{tau}, Q{0.0}, R{0.0};
  double c = 1.0, d = tau;  // c_n, d_n
  Complex xn{1.0};          // x^n
  for (int n = 0; n < 80; ++n) {
    const double nn = n;
    const double c_next = c * (tau2 - nn * nn) / ((2.0 * nn + 1.0) * (nn + 1.0));
    const double d_next = d * (tau2 - (nn + 1.0) * (nn + 1.0)) / ((2.0 * nn + 3.0) * (nn + 1.0));
    Q += c_next * xn;
    R += d_next * xn;
    xn *= x;
    C += c_next * xn;
    S += d_next * xn;
    c = c_next;
    d = d_next;
    if ((std::abs(c) + std::abs(d)) * std::abs(xn) <= limits::kSeriesTermCutoff * (1.0 + std::abs(tau))) break;
  }
  return {C, S, Q, R};
}

// Closed forms in k = acosh kappa (principal: Re k >= 0, the branch of P8).
// Q = 2 sinh^2(k tau / 2)/(kappa - 1) avoids the cancellation in cosh - 1.
MotionScalars motion_closed_form(Complex kappa, double tau) {
  const Complex k = std::acosh(kappa);
  const Complex x = kappa - 1.0;
  const Complex half = std::sinh(0.5 * tau * k);
  const Complex S = std::sinh(tau * k) / std::sinh(k);
  return {std::cosh(tau * k), S, 2.0 * half * half / x, (S - tau) / x};
}

MotionScalars motion_scalars(Complex kappa, double tau) {
  const Complex x = kappa - 1.0;
  if (std::abs(x) * std::max(1.0, tau * tau) <= limits::kPamSeries) return motion_series(x, tau);
  return motion_closed_form(kappa, tau);
}

// The scalar functions behind E (PITA Eq. 39): mu = acosh(kappa)^2 (so M = mu(K))
// and nu = acosh(kappa)^2 / (kappa - 1) (so g = nu(K) w / 2), nu(1) = 2.
// With acosh(kappa)^2 = -acos(kappa)^2 = -4 asin^2(sqrt((1 - kappa)/2)) and the
// series of asin^2:  mu = sum_{n>=1} mu_n x^n,  mu_1 = 2,
//   mu_{n+1} = -mu_n n^2 / ((2n + 1)(n + 1))   (2x - x^2/3 + 4x^3/45 - ...).
using AccelerationScalars = std::array<Complex, 2>;  // mu, nu

AccelerationScalars acceleration_scalars(Complex kappa) {
  const Complex x = kappa - 1.0;
  if (std::abs(x) <= limits::kPamSeries) {
    Complex mu{0.0}, nu{0.0};
    double coefficient = 2.0;  // mu_n
    Complex xn{1.0};           // x^(n-1)
    for (int n = 1; n < 80; ++n) {
      const double nn = n;
      nu += coefficient * xn;
      xn *= x;
      mu += coefficient * xn;
      coefficient *= -nn * nn / ((2.0 * nn + 1.0) * (nn + 1.0));
      if (std::abs(coefficient) * std::abs(xn) <= limits::kSeriesTermCutoff) break;
    }
    return {mu, nu};
  }
  const Complex k = std::acosh(kappa);
  return {k * k, k * k / x};
}

// Matrix functions of the real 2x2 K = m I + N (N traceless, N^2 = s2 I), by
// Sylvester's formula for 2x2 matrices written around the mean eigenvalue:
//     phi(K) = A I + B N,
//     A = (phi(m + s) + phi(m - s)) / 2,   B = phi[m + s, m - s],
// B being the divided difference (phi(m + s) - phi(m - s)) / (2 s). Both
// are even in s, so real. Three cases, none of which cancels:
//  * s2 < 0, complex eigenvalues m +- i t: phi(m - i t) = conj phi(m + i t)
//    (phi is real on the real axis right of -1), so A = Re phi(m + i t) and
//    B = Im phi(m + i t) / t exactly, with no subtraction even for tiny t;
//  * s2 = 0 (K scalar or a Jordan block): B = phi'(m), taken by the same
//    formula with t = limits::kPamComplexStep (complex step, error O(t^2));
//  * s2 > 0, real eigenvalues: the divided difference itself, unless they are
//    closer than limits::kPamCloseEigenvalues (m + 1); then B(s2) is
//    extrapolated from B(0) and B(-s2), both complex steps, as
//    2 B(0) - B(-s2) = B(s2) - phi^(5)(m) s^4 / 60 + ...
// The constructor has already refused eigenvalues on or beyond -1.
template <std::size_t n, class Phi>
std::array<Eigen::Matrix2d, n> matrix_functions(double m, double s2, const Eigen::Matrix2d& N, Phi phi) {
  std::array<double, n> A{}, B{};
  const double h = limits::kPamComplexStep;
  if (s2 <= 0.0) {
    const double t = std::max(std::sqrt(-s2), h);
    const auto v = phi(Complex{m, t});
    for (std::size_t i = 0; i < n; ++i) {
      A[i] = v[i].real();
      B[i] = v[i].imag() / t;
    }
  } else {
    const double s = std::sqrt(s2);
    const auto plus = phi(Complex{m + s, 0.0});
    const auto minus = phi(Complex{m - s, 0.0});
    for (std::size_t i = 0; i < n; ++i) {
      A[i] = 0.5 * (plus[i].real() + minus[i].real());
      B[i] = (plus[i].real() - minus[i].real()) / (2.0 * s);
    }
    if (s < limits::kPamCloseEigenvalues * (m + 1.0)) {
      const auto at_zero = phi(Complex{m, h});
      const auto at_s = phi(Complex{m, std::max(s, h)});
      for (std::size_t i = 0; i < n; ++i) {
        const double b0 = at_zero[i].imag() / h;
        B[i] = s > h ? 2.0 * b0 - at_s[i].imag() / s : b0;
      }
    }
  }
  std::array<Eigen::Matrix2d, n> out;
  for (std::size_t i = 0; i < n; ++i) out[i] = A[i] * Eigen::Matrix2d::Identity() + B[i] * N;
  return out;
}

[[noreturn]] void refuse(const std::string& why) {
  throw MotionDomainError("the persistent affine motion (PAM, PITA Eq. 39) of these keyframes " + why);
}

}  // namespace

PersistentAffineMotion::PersistentAffineMotion(double a, const Affine2& A, double b, const Affine2& B, double c,
                                               const Affine2& C)
    : a_(a), b_(b), c_(c), middle_(B) {
  const double det_B = B.L.determinant();
  if (!(std::abs(det_B) > limits::kPamSingularMiddle * B.L.squaredNorm())) {
    refuse("does not exist: the middle affinity B has a singular linear part");
  }
  const Eigen::Matrix2d B_inverse = B.L.inverse();
  // cosh(sqrt M) = K = L_B^-1 (L_A + L_C)/2: Lin(1) + Lin(-1) = 2 L_B cosh(sqrt M).
  const Eigen::Matrix2d K = B_inverse * (0.5 * (A.L + C.L));
  half_L_change_ = 0.5 * (C.L - A.L);
  half_b_change_ = 0.5 * (C.b - A.b);
  w_ = B_inverse * (A.b + C.b - 2.0 * B.b);
  m_ = 0.5 * K.trace();
  // s^2 = ((K00 - K11)/2)^2 + K01 K10, not m^2 - det K, which cancels
  // (docs/paper-notes.md N15).
  const double half_difference = 0.5 * (K(0, 0) - K(1, 1));
  s2_ = half_difference * half_difference + K(0, 1) * K(1, 0);
  N_ = K - m_ * Eigen::Matrix2d::Identity();
  if (!std::isfinite(m_) || !std::isfinite(s2_) || !w_.allFinite() || !half_L_change_.allFinite() ||
      !half_b_change_.allFinite()) {
    refuse("cannot be built: non-finite keyframes");
  }
  if (s2_ >= 0.0) {
    const double lowest = m_ - std::sqrt(s2_);
    if (std::abs(lowest + 1.0) < limits::kPamSingular) {
      refuse("does not exist: K = L_B^-1 (L_A + L_C)/2 has the eigenvalue -1 (cosh k = -1)");
    }
    if (lowest < -1.0) {
      refuse("does not exist: K = L_B^-1 (L_A + L_C)/2 has the real eigenvalue " + std::to_string(lowest) +
             " < -1, on the branch cut of acosh, where no real (or no unique) M = acosh(K)^2 "
             "exists");
    }
  } else {
    const double t = std::sqrt(-s2_);
    if (std::abs(Complex{m_ + 1.0, t}) < limits::kPamSingular) {
      refuse("does not exist: K = L_B^-1 (L_A + L_C)/2 has the eigenvalue -1 (cosh k = -1)");
    }
    if (m_ < -1.0 && t < limits::kPamBranchCut * std::abs(m_)) {
      refuse(
          "is not defined: the eigenvalues of K = L_B^-1 (L_A + L_C)/2 lie on the branch "
          "cut of acosh (real and < -1 to within rounding)");
    }
  }
}

Affine2 PersistentAffineMotion::at(double t) const {
  const double tau = 2.0 * knot_warp(a_, b_, c_, t) - 1.0;
  const auto f = matrix_functions<4>(m_, s2_, N_, [tau](Complex kappa) { return motion_scalars(kappa, tau); });
  Affine2 U;
  // Lin(tau) = L_B C(tau) + (L_C - L_A)/2 S(tau): Lin'' = Lin M (PITA Eq. 39, F.1).
  U.L = middle_.L * f[kC] + half_L_change_ * f[kS];
  // b(tau) = b_B + (b_C - b_A)/2 tau + 1/2 L_B Q w + 1/4 (L_C - L_A) R w:
  // b'' = Lin g (PITA Eq. 39), b(-1) = b_A, b(0) = b_B, b(1) = b_C since
  // Q(+-1) = I, R(+-1) = 0 and Q(0) = R(0) = 0.
  U.b = middle_.b + half_b_change_ * tau + 0.5 * (middle_.L * (f[kQ] * w_)) + 0.5 * (half_L_change_ * (f[kR] * w_));
  return U;
}

Eigen::Matrix3d PersistentAffineMotion::local_acceleration() const {
  const auto f = matrix_functions<2>(m_, s2_, N_, acceleration_scalars);
  Eigen::Matrix3d E = Eigen::Matrix3d::Zero();
  E.topLeftCorner<2, 2>() = f[0];                // M = acosh(K)^2
  E.topRightCorner<2, 1>() = 0.5 * (f[1] * w_);  // g = M (K - I)^-1 w / 2
  return E;
}

}  // namespace pita
