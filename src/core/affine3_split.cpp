#include "core/affine3_split.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "core/affine_power_of_space.hpp"
#include "core/limits.hpp"

namespace pita {

namespace detail {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Complex = std::complex<double>;

constexpr double kSplitEpsilon = std::numeric_limits<double>::epsilon();

// The largest root of x^3 + p x + q = 0 (a depressed cubic with real
// coefficients): trigonometric when it has three real roots, Cardano's
// formula written without cancellation otherwise.
double depressed_cubic_root(double p, double q) {
  if (p < 0.0) {
    const double m = 2.0 * std::sqrt(-p / 3.0);
    const double cosine = 3.0 * q / (p * m);  // cos(3 phi) of x = m cos(phi)
    if (std::abs(cosine) <= 1.0) return m * std::cos(std::acos(cosine) / 3.0);
  }
  const double discriminant = q * q / 4.0 + p * p * p / 27.0;  // >= 0 here
  const double u = std::cbrt(-q / 2.0 - std::copysign(std::sqrt(std::max(discriminant, 0.0)), q));
  return u == 0.0 ? 0.0 : u - p / (3.0 * u);
}

Vector3d unit_orthogonal(const Vector3d& r) {
  int k = 0;
  r.cwiseAbs().minCoeff(&k);
  return r.cross(Vector3d::Unit(k)).normalized();
}

// A unit null vector of B = L - lambda I, the best of three starts by |B u|:
// the largest cross product of two rows (B of rank 2), a vector orthogonal to
// B's largest row (rank 1: a 2D eigenspace) and e1 (B = 0); then inverse
// iteration while the residual |L u - (u.L u) u| shrinks and exceeds 4 ulps
// of |L| (docs/paper-notes.md N58).
Vector3d eigenvector(const Matrix3d& L, double lambda) {
  const Matrix3d B = L - lambda * Matrix3d::Identity();
  const double scale = std::max(L.norm(), std::numeric_limits<double>::min());
  const auto residual = [&L](const Vector3d& v) { return (L * v - v.dot(L * v) * v).norm(); };
  // The starts are judged by |B u|, not by the residual, so that u belongs to
  // lambda (e1 would win for diag(1, 3, 1) and lambda = 3).
  const Vector3d r0 = B.row(0), r1 = B.row(1), r2 = B.row(2);
  Vector3d cross = r0.cross(r1);
  for (const Vector3d& candidate : {r0.cross(r2), r1.cross(r2)}) {
    if (candidate.squaredNorm() > cross.squaredNorm()) cross = candidate;
  }
  int row = 0;
  B.rowwise().squaredNorm().maxCoeff(&row);
  Vector3d u = Vector3d::UnitX();
  double null_error = (B * u).norm();
  const auto consider = [&](const Vector3d& v) {
    if (!v.allFinite()) return;
    const double e = (B * v).norm();
    if (e < null_error) {
      u = v;
      null_error = e;
    }
  };
  if (cross.norm() > 0.0) consider(cross.normalized());
  if (B.row(row).norm() > 0.0) consider(unit_orthogonal(B.row(row).transpose()));
  double error = residual(u);
  for (int step = 0; step < 3 && error > 4.0 * kSplitEpsilon * scale; ++step) {
    const double rayleigh = u.dot(L * u);
    const Vector3d x = (L - rayleigh * Matrix3d::Identity()).partialPivLu().solve(u);
    if (!x.allFinite() || x.norm() == 0.0) break;
    const Vector3d next = x.normalized();
    const double next_error = residual(next);
    if (!(next_error < error)) break;
    u = next;
    error = next_error;
  }
  return u;
}

}  // namespace

// Whether the three computed eigenvalues are one triple eigenvalue (rounding
// may have made a complex pair of it, or three distinct reals).
bool triple_cluster(const std::array<Complex, 3>& values) {
  const double size = std::max({modulus(values[0]), modulus(values[1]), modulus(values[2]), limits::kTinyScale});
  const double spread =
      std::max({modulus(values[0] - values[1]), modulus(values[0] - values[2]), modulus(values[1] - values[2])});
  return spread <= limits::kEigenvalueCluster * size;
}

// The eigenvalue to split off (see the header): the real one of a complex
// pair; the positive one beside two negative ones; else the most isolated
// (a triple cluster gives tr/3, their mean, which is exact where each root
// is only good to the cube root of rounding).
double split_guess(const Matrix3d& L, const std::array<Complex, 3>& values) {
  if (triple_cluster(values)) return L.trace() / 3.0;
  if (values[1].imag() != 0.0) return values[0].real();
  int positives = 0;
  for (const Complex& v : values) positives += v.real() > 0.0 ? 1 : 0;
  if (positives < 3) return values[0].real();  // the largest: the positive one
  const double d0 = values[0].real() - values[1].real();
  const double d2 = values[1].real() - values[2].real();
  // Isolation of each: nu0 -> d0, nu1 -> min(d0, d2), nu2 -> d2.
  return d0 >= d2 ? values[0].real() : values[2].real();
}

Split split(const Matrix3d& L) {
  const std::array<Complex, 3> values = eigenvalues(L);
  const double guess = split_guess(L, values);
  Vector3d u = eigenvector(L, guess);
  // u's sign: its largest component positive (fixes the half turn, N58).
  int k = 0;
  u.cwiseAbs().maxCoeff(&k);
  if (u(k) < 0.0) u = -u;
  const Vector3d q2 = unit_orthogonal(u);
  Split s;
  s.lambda_guess = guess;
  s.Q.col(0) = u;
  s.Q.col(1) = q2;
  s.Q.col(2) = u.cross(q2);
  return s;
}

// Q^T L Q for the split's basis Q (A.6). With complex eigenvalues of the
// plane block, (q2, q3) are first turned so that its diagonal entries are
// equal (the standardised 2x2 block of the real Schur form, LAPACK's dlanv2):
// its discriminant is then b c, free of the cancellation in
// ((a - d)/2)^2 + b c that a non-normal block would otherwise suffer.
// tan 2 phi = (d - a)/(b + c); the basis stays right-handed.
Matrix3d standardised_split(const Matrix3d& L, Matrix3d& Q) {
  const Matrix3d T = Q.transpose() * L * Q;
  const double a = T(1, 1), b = T(1, 2), c = T(2, 1), d = T(2, 2);
  if (a == d || !(((a - d) / 2.0) * ((a - d) / 2.0) + b * c < 0.0)) return T;
  // cos and sin of phi from those of 2 phi (no trigonometric calls);
  // r >= |d - a| > 0.
  const double x = b + c, y = d - a, r = std::sqrt(x * x + y * y);
  double co = std::sqrt(0.5 * (1.0 + x / r)), si = 0.0;
  if (co > 0.5) {
    si = y / (2.0 * r * co);
  } else {
    si = std::copysign(std::sqrt(0.5 * (1.0 - x / r)), y);
    co = y / (2.0 * r * si);
  }
  const Vector3d q2 = Q.col(1), q3 = Q.col(2);
  Q.col(1) = co * q2 + si * q3;
  Q.col(2) = -si * q2 + co * q3;
  return Q.transpose() * L * Q;
}

}  // namespace detail

std::array<std::complex<double>, 3> eigenvalues(const Eigen::Matrix3d& L) {
  using Eigen::Matrix3d;
  // On 2^-e L, so that the cubic's coefficients neither over- nor underflow.
  const double largest = L.cwiseAbs().maxCoeff();
  int exponent = 0;  // only beyond 2^+-300, where the cubic's products would not fit
  if (largest > 0.0 && std::isfinite(largest) && (largest < 0x1p-300 || largest > 0x1p300)) {
    std::frexp(largest, &exponent);
  }
  const Matrix3d S = exponent == 0 ? L : Matrix3d(L * std::ldexp(1.0, -exponent));
  // z^3 - a z^2 + b z - c: a = trace, b = the principal 2x2 minors, c = det.
  const double a = S.trace();
  const double b = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0) + S(0, 0) * S(2, 2) - S(0, 2) * S(2, 0) + S(1, 1) * S(2, 2) -
                   S(1, 2) * S(2, 1);
  const double c = S.determinant();
  // z = x + a/3: x^3 + p x + q.
  const double p = b - a * a / 3.0;
  const double q = -2.0 * a * a * a / 27.0 + a * b / 3.0 - c;
  const double first = detail::depressed_cubic_root(p, q) + a / 3.0;
  // The other two: sum a - first, product c / first.
  const double half_sum = (a - first) / 2.0;
  const double product = first == 0.0 ? 0.0 : c / first;
  const double discriminant = half_sum * half_sum - product;
  const auto unscaled = [exponent](double x) { return exponent == 0 ? x : std::ldexp(x, exponent); };
  if (discriminant < 0.0) {
    const double imaginary = std::sqrt(-discriminant);
    return {Complex(unscaled(first)), Complex(unscaled(half_sum), unscaled(imaginary)),
            Complex(unscaled(half_sum), -unscaled(imaginary))};
  }
  const double s = std::sqrt(discriminant);
  std::array<double, 3> real = {first, half_sum + s, half_sum - s};
  std::sort(real.begin(), real.end(), [](double x, double y) { return x > y; });
  return {Complex(unscaled(real[0])), Complex(unscaled(real[1])), Complex(unscaled(real[2]))};
}

}  // namespace pita
