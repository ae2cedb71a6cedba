#include "core/affine_power_of_space.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include <Eigen/LU>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/affine3_split.hpp"
#include "core/limits.hpp"
#include "core/number_text.hpp"

namespace pita {

namespace {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;
using Complex = std::complex<double>;
using detail::modulus;
using detail::Split;
using detail::split_guess;
using detail::triple_cluster;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

using number_text::g6;

std::string complex_text(Complex z) {
  if (z.imag() == 0.0) return g6(z.real());
  return g6(z.real()) + (z.imag() < 0.0 ? " - " : " + ") + g6(std::abs(z.imag())) + "i";
}

std::string eigenvalue_text(Complex a, Complex b, Complex c) {
  return complex_text(a) + ", " + complex_text(b) + " and " + complex_text(c);
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

// A plane block within the 2D EAR's half-turn tolerance of -rho I is made
// exactly that (docs/paper-notes.md N58): rounding of the basis leaves it a
// non-normal matrix whose complex eigenvalues -rho +- i 1e-16 would give a
// square root that is no rotation (2D never needs this: its entries are the
// input's own).
void snap_to_half_turn(Matrix2d& M) {
  const double r = M.trace() / 2.0;
  if (r < 0.0 && (M - r * Matrix2d::Identity()).cwiseAbs().maxCoeff() <= limits::kHalfTurn * -r) {
    M = r * Matrix2d::Identity();
  }
}

}  // namespace

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

AffinePowers<Affine3>::AffinePowers(const Affine3& A) : A_(A) {
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
  const Split s = detail::split(A.L);
  Q_ = s.Q;
  const Matrix3d T = detail::standardised_split(A.L, Q_);
  // The column below lambda, which the split drops: rounding (a few ulps of
  // |L|) when u is an eigenvector to working precision.
  const double dropped = T.block<2, 1>(1, 0).norm();
  lambda_ = T(0, 0);
  w_ = T.block<1, 2>(0, 1).transpose();
  Matrix2d M = T.block<2, 2>(1, 1);
  snap_to_half_turn(M);
  set_translation(A.b);

  const Eigenvalues plane_values = pita::eigenvalues(M);
  const Complex mu1(plane_values.re1, plane_values.im1), mu2(plane_values.re2, plane_values.im2);
  if (!(lambda_ > 0.0)) {
    // Only with det L > 0 rounded away (the three eigenvalues ~ 0, or a negative
    // lambda picked from three nearly equal negatives): no real log either way.
    throw NoRealLogarithm("the linear part has the eigenvalues " + eigenvalue_text(Complex(lambda_), mu1, mu2) +
                              ": no positive eigenvalue to split off (A.6); no real logarithm",
                          RootCase::G3);
  }
  try {
    plane_.emplace(Affine2{M, c_});
    relative_.emplace(Affine2{Matrix2d(M.transpose() / lambda_), Vector2d::Zero()});
  } catch (const NoRealLogarithm&) {
    const bool real_pair = plane_values.im1 == 0.0;
    throw NoRealLogarithm("the linear part has the eigenvalues " + eigenvalue_text(Complex(lambda_), mu1, mu2) +
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
    // Three eigenvalues close to 1 are found by the cubic only to the cube
    // root of rounding, and u may then miss the eigenvector by far more than
    // rounding: the column the split drops is as large as L - I itself, and
    // so would be the error of L^t. There L^t is the binomial series, which
    // needs no split (docs/paper-notes.md N80).
    linear_by_series_ = dropped > limits::kSplitResidual * A.L.norm();
  } else if (from_one >= from_plane) {
    corner_ = Corner::over_lambda_minus_one;
  } else {
    corner_ = Corner::over_lambda_minus_M;
    lean_solve_ = (lambda_ * Matrix2d::Identity() - M).inverse() * c_;
  }
}

void AffinePowers<Affine3>::set_translation(const Vector3d& b) {
  A_.b = b;
  const Vector3d moved = Q_.transpose() * b;
  beta_ = moved(0);
  c_ = moved.tail<2>();
}

AffinePowers<Affine3> AffinePowers<Affine3>::with_translation(const Vector3d& b) const {
  if (!b.allFinite()) throw NoRealLogarithm("the affinity has a non-finite entry", RootCase::G3);
  AffinePowers powers = *this;
  powers.set_translation(b);
  powers.plane_ = plane_->with_translation(powers.c_);  // [M | c]
  if (corner_ == Corner::over_lambda_minus_M) {
    powers.lean_solve_ = (lambda_ * Matrix2d::Identity() - M_).inverse() * powers.c_;  // as the constructor's
  }
  return powers;
}

Affine3 AffinePowers<Affine3>::velocity(double t) const {
  const Affine3 generator = log();
  const Affine3 power = at(t);
  return {generator.L * power.L, generator.L * power.b + generator.b};
}

Affine3 AffinePowers<Affine3>::split_log() const {
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
    // Near the identity, with E = L - I, log L = sum_{n>=1} (-1)^{n-1} E^n / n,
    // right relative to E, where the split's is right relative to L only (N80).
    const Matrix3d E = A_.L - Matrix3d::Identity();
    Matrix3d linear = Matrix3d::Zero(), power = E;
    for (int n = 1, small_terms = 0; n <= 400 && small_terms < 3; ++n) {
      const Matrix3d term = ((n % 2 == 1) ? 1.0 : -1.0) / n * power;
      linear += term;
      small_terms = term.norm() <= limits::kSeriesTermCutoff * linear.norm() ? small_terms + 1 : 0;
      power = E * power;
    }
    log.L = linear;
    // l(I + E) b = sum_{n>=1} (-1)^{n-1} E^{n-1} b / n.
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
                              : l_lambda * w_.dot(lean_solve_) - w_.dot(plane_->log_translation(lean_solve_));
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

Affine3 AffinePowers<Affine3>::log() const {
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

Vector3d AffinePowers<Affine3>::unit_series(double t) const {
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

Matrix3d AffinePowers<Affine3>::unit_series_linear(double t) const {
  // (I + E)^t = sum_{n>=0} C(t, n) E^n (spectral radius of E <= 1/4); ended
  // as unit_series is, by three small terms in a row.
  const Matrix3d E = A_.L - Matrix3d::Identity();
  Matrix3d sum = Matrix3d::Identity(), x = E;
  double binomial = t;
  int small_terms = 0;
  for (int n = 1; n <= 400 && small_terms < 3; ++n) {
    const Matrix3d term = binomial * x;
    sum += term;
    small_terms = term.norm() <= limits::kSeriesTermCutoff * sum.norm() ? small_terms + 1 : 0;
    x = E * x;
    binomial *= (t - n) / (n + 1.0);
  }
  return sum;
}

Affine3 AffinePowers<Affine3>::at_small(double t) const {
  if (linear_by_series_) return {unit_series_linear(t), unit_series(t)};
  // The plane: [M | c]^t = [M^t | g_t(M) c] (2D EAR).
  const Affine2 plane = plane_->at(t);
  // The lean: w^T (z^t)[lambda, M] = lambda^(t-1) (g_t(M^T / lambda) w)^T.
  const Vector2d lean = std::exp((t - 1.0) * log_lambda_) * relative_->power_with_translation(t, w_).b;
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
                            : g_lambda * w_.dot(lean_solve_) - w_.dot(plane_->power_with_translation(t, lean_solve_).b);
  result.b = Q_ * Vector3d(g_lambda * beta_ + corner, plane.b(0), plane.b(1));
  return result;
}

Affine3 AffinePowers<Affine3>::at(double t) const {
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

Affine3 affine_power(const Affine3& A, double t) { return AffinePowers(A).at(t); }

Affine3 log(const Affine3& A) { return AffinePowers(A).log(); }

Affine3 exp(const Affine3& generator) {
  Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
  H.topLeftCorner<3, 3>() = generator.L;
  H.topRightCorner<3, 1>() = generator.b;
  return affine3_of(Eigen::Matrix4d(H.exp()));
}

}  // namespace pita
