#include "core/affine_power3.hpp"

#include <Eigen/LU>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "core/limits.hpp"
#include "core/number_text.hpp"

namespace pita {

namespace {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;
using Complex = std::complex<double>;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

using number_text::g6;

std::string complex_text(Complex z) {
  if (z.imag() == 0.0) return g6(z.real());
  return g6(z.real()) + (z.imag() < 0.0 ? " - " : " + ") + g6(std::abs(z.imag())) + "i";
}

std::string eigenvalue_text(Complex a, Complex b, Complex c) {
  return complex_text(a) + ", " + complex_text(b) + " and " + complex_text(c);
}

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

// One real eigenvalue lambda of L and an orthonormal right-handed basis
// Q = [u, q2, q3] with L u ~ lambda u: the first step of the real Schur form
// (docs/paper-notes.md N58).
struct Split {
  double lambda_guess;
  Matrix3d Q;
};

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
  const auto residual = [&L](const Vector3d& v) {
    return (L * v - v.dot(L * v) * v).norm();
  };
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
  for (int step = 0; step < 3 && error > 4.0 * kEpsilon * scale; ++step) {
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

// |z| without hypot (its overflow care is not needed for eigenvalues of a
// finite 3x3, and it is slow).
double modulus(Complex z) { return std::sqrt(z.real() * z.real() + z.imag() * z.imag()); }

// Whether the three computed eigenvalues are one triple eigenvalue (rounding
// may have made a complex pair of it, or three distinct reals).
bool triple_cluster(const std::array<Complex, 3>& values) {
  const double size = std::max({modulus(values[0]), modulus(values[1]), modulus(values[2]), limits::kTinyScale});
  const double spread = std::max({modulus(values[0] - values[1]), modulus(values[0] - values[2]),
                                  modulus(values[1] - values[2])});
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

// l(lambda) = ln(lambda)/(lambda - 1) and g_t(lambda) = (lambda^t - 1)/(lambda - 1),
// exact near lambda = 1 (log1p, expm1).
double log_ratio(double lambda) {
  const double mu = lambda - 1.0;
  return mu == 0.0 ? 1.0 : std::log1p(mu) / mu;
}
double power_ratio(double lambda, double t) {
  const double mu = lambda - 1.0;
  return mu == 0.0 ? t : std::expm1(t * std::log1p(mu)) / mu;
}

// The NaN affinity (no power at a non-finite time).
Affine3 not_a_number() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Affine3{Matrix3d::Constant(nan), Vector3d::Constant(nan)};
}

}  // namespace

std::array<Complex, 3> eigenvalues(const Matrix3d& L) {
  // On 2^-e L, so that the cubic's coefficients neither over- nor underflow.
  const double largest = L.cwiseAbs().maxCoeff();
  int exponent = 0;  // only beyond 2^+-300, where the cubic's products would not fit
  if (largest > 0.0 && std::isfinite(largest) && (largest < 0x1p-300 || largest > 0x1p300)) {
    std::frexp(largest, &exponent);
  }
  const Matrix3d S = exponent == 0 ? L : Matrix3d(L * std::ldexp(1.0, -exponent));
  // z^3 - a z^2 + b z - c: a = trace, b = the principal 2x2 minors, c = det.
  const double a = S.trace();
  const double b = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0) + S(0, 0) * S(2, 2) - S(0, 2) * S(2, 0) +
                   S(1, 1) * S(2, 2) - S(1, 2) * S(2, 1);
  const double c = S.determinant();
  // z = x + a/3: x^3 + p x + q.
  const double p = b - a * a / 3.0;
  const double q = -2.0 * a * a * a / 27.0 + a * b / 3.0 - c;
  const double first = depressed_cubic_root(p, q) + a / 3.0;
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

std::optional<Vector3d> fixed_point(const Affine3& A) {
  if (!A.L.allFinite() || !A.b.allFinite()) return std::nullopt;
  const std::array<Complex, 3> values = eigenvalues(A.L);
  const double guess = split_guess(A.L, values);
  for (const Complex& v : values) {
    // A triple cluster is its mean (split_guess), exact where the roots are not.
    const Complex value = triple_cluster(values) ? Complex(guess) : v;
    if (modulus(value - 1.0) <= limits::kUnitEigenvalue) return std::nullopt;
  }
  const Vector3d q = (Matrix3d::Identity() - A.L).partialPivLu().solve(A.b);  // (I - L) q = b
  if (!q.allFinite()) return std::nullopt;
  return q;
}

AffinePowers3::AffinePowers3(const Affine3& A) : A_(A) {
  if (!A.L.allFinite() || !A.b.allFinite()) {
    throw NoRealLogarithm("the affinity has a non-finite entry", RootCase::G3);
  }
  const double det = A.L.determinant();
  if (!(det > 0.0)) {
    const std::array<Complex, 3> v = eigenvalues(A.L);
    throw NoRealLogarithm("the linear part has determinant " + g6(det) + " <= 0 (eigenvalues " +
                              eigenvalue_text(v[0], v[1], v[2]) +
                              "): it is not orientation-preserving, and no continuous motion of "
                              "affinities joins it to the identity (Sec. 2.1)",
                          RootCase::G3);
  }

  // The split (A.6): Q^T A Q = [[lambda, w^T, beta], [0, M, c], [0, 0, 1]];
  // the column below lambda is the residual of the eigenvector, dropped.
  const Split s = split(A.L);
  Q_ = s.Q;
  Matrix3d T = Q_.transpose() * A.L * Q_;
  {
    // With complex eigenvalues, turn (q2, q3) so that M's diagonal entries are
    // equal (the standardised 2x2 block of the real Schur form, LAPACK's
    // dlanv2): its discriminant is then b c, free of the cancellation in
    // ((a - d)/2)^2 + b c that a non-normal block would otherwise suffer.
    // tan 2 phi = (d - a)/(b + c); the basis stays right-handed.
    const double a = T(1, 1), b = T(1, 2), c = T(2, 1), d = T(2, 2);
    if (a != d && ((a - d) / 2.0) * ((a - d) / 2.0) + b * c < 0.0) {
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
      const Vector3d q2 = Q_.col(1), q3 = Q_.col(2);
      Q_.col(1) = co * q2 + si * q3;
      Q_.col(2) = -si * q2 + co * q3;
      T = Q_.transpose() * A.L * Q_;
    }
  }
  const Vector3d moved = Q_.transpose() * A.b;
  lambda_ = T(0, 0);
  w_ = T.block<1, 2>(0, 1).transpose();
  Matrix2d M = T.block<2, 2>(1, 1);
  // A plane block within the 2D EAR's half-turn tolerance of -rho I is made
  // exactly that (docs/paper-notes.md N58): rounding of the basis leaves it a
  // non-normal matrix whose complex eigenvalues -rho +- i 1e-16 would give a
  // square root that is no rotation (2D never needs this: its entries are
  // the input's own).
  {
    const double r = M.trace() / 2.0;
    if (r < 0.0 && (M - r * Matrix2d::Identity()).cwiseAbs().maxCoeff() <= limits::kHalfTurn * -r) {
      M = r * Matrix2d::Identity();
    }
  }
  beta_ = moved(0);
  c_ = moved.tail<2>();

  const Eigenvalues plane_values = pita::eigenvalues(M);
  const Complex mu1(plane_values.re1, plane_values.im1), mu2(plane_values.re2, plane_values.im2);
  if (!(lambda_ > 0.0)) {
    // Only with det L > 0 rounded away (the three eigenvalues ~ 0, or a negative
    // lambda picked from three nearly equal negatives): no real log either way.
    throw NoRealLogarithm("the linear part has the eigenvalues " +
                              eigenvalue_text(Complex(lambda_), mu1, mu2) +
                              ": no positive eigenvalue to split off (A.6); no real logarithm",
                          RootCase::G3);
  }
  try {
    plane_.emplace(Affine2{M, c_});
    relative_.emplace(Affine2{Matrix2d(M.transpose() / lambda_), Vector2d::Zero()});
  } catch (const NoRealLogarithm&) {
    const bool real_pair = plane_values.im1 == 0.0;
    throw NoRealLogarithm(
        "the linear part has the eigenvalues " + eigenvalue_text(Complex(lambda_), mu1, mu2) +
            (real_pair && plane_values.re1 != plane_values.re2
                 ? ": two distinct negative eigenvalues"
                 : ": a negative eigenvalue without two independent eigenvectors") +
            " (case G3 on the plane beside the eigenvalue " + g6(lambda_) +
            "): it has no real logarithm (Culver, Sec. 5.1)",
        RootCase::G3);
  }
  log_lambda_ = std::log1p(lambda_ - 1.0);

  // The corner's formula (limits.hpp, "EAR in 3D").
  const double radius = std::max({std::abs(lambda_ - 1.0), modulus(mu1 - 1.0), modulus(mu2 - 1.0)});
  const double from_one = std::abs(lambda_ - 1.0);
  const double from_plane = std::min(modulus(lambda_ - mu1), modulus(lambda_ - mu2));
  M_ = M;
  // The Sylvester lean of log() needs lambda I - M well conditioned.
  lean_by_sylvester_ = from_plane >= limits::kSylvesterLeanGap * std::max({lambda_, modulus(mu1), modulus(mu2)});
  if (radius <= limits::kUnitSeriesRadius) {
    corner_ = Corner::unit_series;
  } else if (from_one >= from_plane) {
    corner_ = Corner::over_lambda_minus_one;
  } else {
    corner_ = Corner::over_lambda_minus_M;
    lean_solve_ = (lambda_ * Matrix2d::Identity() - M).inverse() * c_;
  }

}

Affine3 AffinePowers3::split_log() const {
  Affine3 log;
  // log L = Q [[ln lambda, w^T ln[lambda, M]], [0, log M]] Q^T with
  // ln[lambda, M] = l(M / lambda) / lambda (transposed: the row w^T acts on the left).
  // When lambda is well apart from M's eigenvalues, the lean row comes instead
  // from the Sylvester equation that log T commutes with T (Parlett):
  // lambda x^T - x^T M = ln(lambda) w^T - w^T log M, so
  // x = (ln(lambda) I - log M)^T (lambda I - M)^-T w. It is then consistent
  // with the plane's log as computed, and exp(log A) = A gains up to 30x on
  // non-normal L (N58, "the lean row").
  Vector2d lean_log = relative_->log_translation(w_) / lambda_;
  if (lean_by_sylvester_) {
    lean_log = ((log_lambda_ * Matrix2d::Identity() - plane_->linear_log()).transpose() *
                (lambda_ * Matrix2d::Identity() - M_).transpose().partialPivLu().solve(w_));
  }
  Matrix3d log_T = Matrix3d::Zero();
  log_T(0, 0) = log_lambda_;
  log_T.block<1, 2>(0, 1) = lean_log.transpose();
  log_T.block<2, 2>(1, 1) = plane_->linear_log();
  log.L = Q_ * log_T * Q_.transpose();
  // Its translation l(L) b: the same block formula with f = ln.
  if (corner_ == Corner::unit_series) {
    // l(I + E) b = sum_{n>=1} (-1)^{n-1} E^{n-1} b / n.
    const Matrix3d E = A_.L - Matrix3d::Identity();
    Vector3d sum = Vector3d::Zero(), x = A_.b;
    int small_terms = 0;
    for (int n = 1; n <= 400 && small_terms < 3; ++n) {
      const Vector3d term = ((n % 2 == 1) ? 1.0 : -1.0) / n * x;
      sum += term;
      small_terms = term.norm() <= limits::kSeriesTermCutoff * sum.norm() ? small_terms + 1 : 0;
      x = E * x;
    }
    log.b = sum;
  } else {
    const Vector2d plane_log = plane_->log_translation(c_);
    const double l_lambda = log_ratio(lambda_);
    const double corner = corner_ == Corner::over_lambda_minus_one
                              ? (lean_log.dot(c_) - w_.dot(plane_log)) / (lambda_ - 1.0)
                              : l_lambda * w_.dot(lean_solve_) -
                                    w_.dot(plane_->log_translation(lean_solve_));
    log.b = Q_ * Vector3d(l_lambda * beta_ + corner, plane_log(0), plane_log(1));
  }
  return log;
}

namespace {

using Matrix4l = Eigen::Matrix<long double, 4, 4>;

Matrix4l homogeneous_long(const Affine3& A, double corner) {
  Matrix4l H = Matrix4l::Zero();
  H.topLeftCorner<3, 3>() = A.L.cast<long double>();
  H.topRightCorner<3, 1>() = A.b.cast<long double>();
  H(3, 3) = corner;
  return H;
}

// |exp(X) - H|_F / max(|H|_F, 1), exp in long double: how far a log X misses.
long double log_residual(const Matrix4l& X, const Matrix4l& H) {
  return (Matrix4l(X.exp()) - H).norm() / std::max(H.norm(), 1.0L);
}

}  // namespace

Affine3 AffinePowers3::log() const {
  // Newton's method on exp(X) = A (N58, "refinement"): the residual
  // R = A - exp(X) in long double, the Frechet derivative of exp at X by the
  // block identity exp([[X, E], [0, X]]) = [[e^X, Dexp_X(E)], [0, e^X]]
  // (Higham, Functions of Matrices, Thm. 3.6) on the 12 affine directions E,
  // and Dexp_X(dX) = R solved for the correction. Mixed-precision iterative
  // refinement, as for linear systems: the split's log is right to ~1e-12 on
  // strongly non-normal L; up to kLogRefineSteps steps, each judged after
  // rounding to double as it is returned, bring exp(log A) to the rounding
  // of the log itself. X stays in long double between steps.
  const Affine3 split = split_log();
  const Matrix4l H = homogeneous_long(A_, 1.0);
  Affine3 best = split;
  long double best_residual = log_residual(homogeneous_long(split, 0.0), H);
  const Matrix4l start = homogeneous_long(split, 0.0);
  Matrix4l X = start;
  using Matrix8l = Eigen::Matrix<long double, 8, 8>;
  for (int n = 0; n < limits::kLogRefineSteps && best_residual > limits::kLogRefineResidual; ++n) {
    const Matrix4l R = H - Matrix4l(X.exp());
    Eigen::Matrix<long double, 12, 12> J;
    Eigen::Matrix<long double, 12, 1> r;
    for (int k = 0; k < 12; ++k) {
      Matrix8l B = Matrix8l::Zero();
      B.topLeftCorner<4, 4>() = X;
      B.bottomRightCorner<4, 4>() = X;
      B(k / 4, 4 + k % 4) = 1.0L;
      const Matrix8l E = B.exp();
      for (int m = 0; m < 12; ++m) J(m, k) = E(m / 4, 4 + m % 4);
      r(k) = R(k / 4, k % 4);
    }
    const Eigen::Matrix<long double, 12, 1> step = J.fullPivLu().solve(r);
    if (!step.allFinite()) break;
    for (int m = 0; m < 12; ++m) X(m / 4, m % 4) += step(m);
    // Never away from the split's branch (near a half turn Dexp is nearly singular).
    if ((X - start).norm() > limits::kLogRefineStep * std::max(start.norm(), 1.0L)) break;
    Affine3 rounded;
    rounded.L = X.topLeftCorner<3, 3>().cast<double>();
    rounded.b = X.topRightCorner<3, 1>().cast<double>();
    const long double residual = log_residual(homogeneous_long(rounded, 0.0), H);
    if (residual < best_residual) {
      best = rounded;
      best_residual = residual;
    }
  }
  return best;
}

Vector3d AffinePowers3::unit_series(double t) const {
  // g_t(I + E) b = sum_{n>=1} C(t, n) E^{n-1} b (spectral radius of E <= 1/4).
  // Three small terms in a row end it: by Cayley-Hamilton every later one is
  // a combination of them.
  const Matrix3d E = A_.L - Matrix3d::Identity();
  Vector3d sum = Vector3d::Zero(), x = A_.b;
  double binomial = t;
  int small_terms = 0;
  for (int n = 1; n <= 400 && small_terms < 3; ++n) {
    const Vector3d term = binomial * x;
    sum += term;
    small_terms = term.norm() <= limits::kSeriesTermCutoff * sum.norm() ? small_terms + 1 : 0;
    x = E * x;
    binomial *= (t - n) / (n + 1.0);
  }
  return sum;
}

Affine3 AffinePowers3::at_small(double t) const {
  // The plane: [M | c]^t = [M^t | g_t(M) c] (2D EAR).
  const Affine2 plane = plane_->at(t);
  // The lean: w^T (z^t)[lambda, M] = lambda^(t-1) (g_t(M^T / lambda) w)^T.
  const Vector2d lean =
      std::exp((t - 1.0) * log_lambda_) * relative_->power_with_translation(t, w_).b;
  Matrix3d T = Matrix3d::Zero();
  T(0, 0) = std::exp(t * log_lambda_);
  T.block<1, 2>(0, 1) = lean.transpose();
  T.block<2, 2>(1, 1) = plane.L;
  Affine3 result;
  result.L = Q_ * T * Q_.transpose();
  if (corner_ == Corner::unit_series) {
    result.b = unit_series(t);
    return result;
  }
  // The corner f[lambda, 1] beta + w^T f[lambda, M, 1] c.
  const double g_lambda = power_ratio(lambda_, t);
  const double corner = corner_ == Corner::over_lambda_minus_one
                            ? (lean.dot(c_) - w_.dot(plane.b)) / (lambda_ - 1.0)
                            : g_lambda * w_.dot(lean_solve_) -
                                  w_.dot(plane_->power_with_translation(t, lean_solve_).b);
  result.b = Q_ * Vector3d(g_lambda * beta_ + corner, plane.b(0), plane.b(1));
  return result;
}

Affine3 AffinePowers3::at(double t) const {
  if (!std::isfinite(t)) return not_a_number();
  if (t == 0.0) return Affine3::identity();
  if (t == 1.0) return A_;
  if (corner_ != Corner::unit_series || std::abs(t) <= limits::kUnitSeriesMaxTime) return at_small(t);
  // A^t = (A^{t/2^k})^{2^k}, each factor within the series' range.
  int halvings = 0;
  double step = t;
  while (std::abs(step) > limits::kUnitSeriesMaxTime) {
    step /= 2.0;
    ++halvings;
  }
  Affine3 result = at_small(step);
  for (int i = 0; i < halvings; ++i) result = compose(result, result);
  return result;
}

Affine3 affine_power(const Affine3& A, double t) { return AffinePowers3(A).at(t); }

Affine3 log(const Affine3& A) { return AffinePowers3(A).log(); }

Affine3 exp(const Affine3& generator) {
  Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
  H.topLeftCorner<3, 3>() = generator.L;
  H.topRightCorner<3, 1>() = generator.b;
  return affine3_of(Eigen::Matrix4d(H.exp()));
}

}  // namespace pita
