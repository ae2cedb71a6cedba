#include "core/exp_of_parts.hpp"

#include <cmath>

#include "core/limits.hpp"

namespace pita::detail {

namespace {

using Eigen::Matrix2d;

// cosh(sqrt z), cosh(sqrt z) - 1 and sinh(sqrt z)/sqrt z for real z (cos and
// sin of sqrt(-z) when z < 0): the entire functions of SAM Eq. 11.
double cosh_sqrt(double z) {
  if (std::abs(z) < limits::kExpSeries) {
    return 1.0 + z / 2.0 * (1.0 + z / 12.0 * (1.0 + z / 30.0 * (1.0 + z / 56.0)));
  }
  return z > 0.0 ? std::cosh(std::sqrt(z)) : std::cos(std::sqrt(-z));
}
double cosh_sqrt_minus_one(double z) {
  if (std::abs(z) < limits::kExpSeries) {
    return z / 2.0 * (1.0 + z / 12.0 * (1.0 + z / 30.0 * (1.0 + z / 56.0 * (1.0 + z / 90.0))));
  }
  if (z > 0.0) {
    const double h = std::sinh(std::sqrt(z) / 2.0);
    return 2.0 * h * h;
  }
  const double h = std::sin(std::sqrt(-z) / 2.0);
  return -2.0 * h * h;
}
double sinh_sqrt_ratio(double z) {
  if (std::abs(z) < limits::kExpSeries) {
    return 1.0 + z / 6.0 * (1.0 + z / 20.0 * (1.0 + z / 42.0 * (1.0 + z / 72.0 * (1.0 + z / 110.0))));
  }
  if (z > 0.0) {
    const double w = std::sqrt(z);
    return std::sinh(w) / w;
  }
  const double w = std::sqrt(-z);
  return std::sin(w) / w;
}

// e^{tC} for C = x I + M, M traceless with M^2 = gamma I (SAM Eq. 11, written
// with the discriminant gamma of C so that it stays real):
//   e^{tC} = e^{tx} (cosh(t sqrt gamma) I + t sinh(t sqrt gamma)/(t sqrt gamma) M),
// exact as gamma -> 0 (Jordan blocks). With real eigenvalues x +- sigma and
// |t sigma| > limits::kExpProjectors, through the spectral projectors
// instead, e^{t(x + sigma)} P+ + e^{t(x - sigma)} P-, P+- = (I +- M/sigma)/2:
// cosh and sinh of a large t sigma would cancel in the small eigenvalue's
// direction (a stretch diag(1e6, 1e-6) would lose 12 digits of its 1e-6, and
// diag(0.5, 0.25)^100 all of them).
bool use_projectors(double gamma, double t) {
  return gamma > 0.0 && t * t * gamma > limits::kExpProjectors * limits::kExpProjectors;
}

// f(x + sigma) P+ + f(x - sigma) P-: a function of C = x I + M through its
// spectral projectors P+- = (I +- M/sigma)/2 (real eigenvalues x +- sigma).
template <typename Function>
Matrix2d spectral(double x, const Matrix2d& M, double sigma, Function f) {
  const Matrix2d half_M = M / (2.0 * sigma);
  return f(x + sigma) * (0.5 * Matrix2d::Identity() + half_M) + f(x - sigma) * (0.5 * Matrix2d::Identity() - half_M);
}

}  // namespace

Matrix2d exp_of_parts(double x, const Matrix2d& M, double gamma, double t) {
  if (use_projectors(gamma, t)) {
    return spectral(x, M, std::sqrt(gamma), [t](double lambda) { return std::exp(t * lambda); });
  }
  const double z = t * t * gamma;
  return std::exp(t * x) * (cosh_sqrt(z) * Matrix2d::Identity() + t * sinh_sqrt_ratio(z) * M);
}

// e^{tC} - I, exact for small t: expm1 in each term.
Matrix2d exp_of_parts_minus_identity(double x, const Matrix2d& M, double gamma, double t) {
  if (use_projectors(gamma, t)) {
    return spectral(x, M, std::sqrt(gamma), [t](double lambda) { return std::expm1(t * lambda); });
  }
  // e^{tx} ch - 1 = expm1(tx) ch + (ch - 1).
  const double z = t * t * gamma;
  return (std::expm1(t * x) * cosh_sqrt(z) + cosh_sqrt_minus_one(z)) * Matrix2d::Identity() +
         std::exp(t * x) * t * sinh_sqrt_ratio(z) * M;
}

}  // namespace pita::detail
