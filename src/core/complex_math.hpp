// Small complex-number helpers shared by the plane algebra of the core.
#pragma once

#include <cmath>
#include <complex>
#include <numbers>

namespace pita {

using Complex = std::complex<double>;

inline constexpr double kPi = std::numbers::pi;

// e^z - 1 without cancellation for small |z| (the standard library has no
// complex expm1). Real part: (e^x - 1) cos y + (cos y - 1).
inline Complex expm1(Complex z) {
  const double x = z.real();
  const double y = z.imag();
  const double em1 = std::expm1(x);
  const double s = std::sin(y);
  const double c = std::cos(y);
  // cos y - 1 = -sin^2 y / (1 + cos y) is exact-ish where it matters (c > 0).
  const double cm1 = c > 0.0 ? -s * s / (1.0 + c) : c - 1.0;
  const double ex = std::abs(x) < 0.5 ? em1 + 1.0 : std::exp(x);
  return {em1 * c + cm1, ex * s};
}

// Both e^z and e^z - 1, each accurate (one exp and one sincos when |Re z| is
// small, which is the common case).
struct ExpPair {
  Complex exp;     // e^z
  Complex expm1;   // e^z - 1
  double modulus;  // |e^z| = e^{Re z}
};
inline ExpPair exp_pair(Complex z) {
  const double x = z.real();
  const double y = z.imag();
  const double s = std::sin(y);
  const double c = std::cos(y);
  const double cm1 = c > 0.0 ? -s * s / (1.0 + c) : c - 1.0;
  double ex;
  double em1;
  if (std::abs(x) < 0.5) {
    em1 = std::expm1(x);
    ex = em1 + 1.0;
  } else {
    ex = std::exp(x);
    em1 = ex - 1.0;
  }
  return {{ex * c, ex * s}, {em1 * c + cm1, ex * s}, ex};
}

// The principal angle of winding w, in (-pi, pi] (Sec. 2.1: zero-turn).
inline double principal_angle(double w) {
  double r = std::remainder(w, 2.0 * std::numbers::pi);  // in [-pi, pi]
  if (r <= -std::numbers::pi) r += 2.0 * std::numbers::pi;
  return r;
}

inline double squared_norm(Complex z) { return std::norm(z); }

}  // namespace pita
