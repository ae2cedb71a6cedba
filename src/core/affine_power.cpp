#include "core/affine_power.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <tuple>

#include <unsupported/Eigen/MatrixFunctions>

#include "core/exp_of_parts.hpp"
#include "core/limits.hpp"
#include "core/number_text.hpp"

namespace pita {

namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;

using detail::exp_of_parts;
using detail::exp_of_parts_minus_identity;
using number_text::g6;

// The quantities of A.5 read off L = [[a, b], [c, d]], computed on the scaled
// L^ = 2^-exponent L so that no product of entries over- or underflows (the
// poses may hold 1e+-100, so C o B^-1 may reach 1e+-200 and its determinant
// 1e+-400). The quantities of E = L - I use exponent_E = max(exponent, 0): a
// tiny L has E ~ -I, which needs no scaling.
struct Characteristics {
  int exponent;  // 0 unless L's largest entry is beyond 2^+-400
  double r;      // trace / 2                                       (of L^)
  double delta;  // ((a - d)/2)^2 + b c = r^2 - det (discriminant)  (of L^)
  double det;    //                                                 (of L^)
  double n_max;  // the largest entry of N = L - r I                (of L^)
  int exponent_E;
  double delta_E;  // delta of 2^-exponent_E L
  double trace_E;  // trace and determinant of 2^-exponent_E (L - I)
  double det_E;
  double det_minus_one;  // det L - 1 = trace E + det E (exponent_E = 0; exact near I)
};

// p q - r s to within an ulp or two of the exact value (Kahan's algorithm
// with fma): the determinant of a strong stretch, e.g. eigenvalues 1e3 and
// 1e-3 with entries ~500, would otherwise lose 5 digits to cancellation.
double cross_difference(double p, double q, double r, double s) {
  const double rs = r * s;
  const double error = std::fma(-r, s, rs);  // rs - r s exactly
  return std::fma(p, q, -rs) + error;
}

int scale_exponent(const Matrix2d& L) {
  const double largest = L.cwiseAbs().maxCoeff();
  if (largest == 0.0 || !std::isfinite(largest) || (largest >= 0x1p-400 && largest <= 0x1p400)) {
    return 0;
  }
  int exponent = 0;
  std::frexp(largest, &exponent);
  return exponent;
}

Characteristics characteristics(const Matrix2d& L) {
  Characteristics k{};
  k.exponent = scale_exponent(L);
  const Matrix2d S = k.exponent == 0 ? L : Matrix2d(L * std::ldexp(1.0, -k.exponent));
  const double a = S(0, 0), b = S(0, 1), c = S(1, 0), d = S(1, 1);
  const double h = (a - d) / 2.0;
  k.r = (a + d) / 2.0;
  k.delta = cross_difference(h, h, -b, c);  // h^2 + b c
  k.det = cross_difference(a, d, b, c);
  k.n_max = std::max({std::abs(h), std::abs(b), std::abs(c)});

  k.exponent_E = std::max(k.exponent, 0);
  const double scale_E = std::ldexp(1.0, -k.exponent_E);
  const double one = scale_E;  // the identity, scaled
  const double aE = L(0, 0) * scale_E, bE = L(0, 1) * scale_E, cE = L(1, 0) * scale_E, dE = L(1, 1) * scale_E;
  const double hE = (aE - dE) / 2.0;
  k.delta_E = cross_difference(hE, hE, -bE, cE);
  k.trace_E = (aE - one) + (dE - one);
  k.det_E = cross_difference(aE - one, dE - one, bE, cE);
  k.det_minus_one = k.trace_E + k.det_E;
  return k;
}

// The real eigenvalues of E = L - I when delta >= 0, the larger in magnitude
// first (the other from det E / first, without cancellation); unscaled.
std::pair<double, double> real_unit_offsets(const Characteristics& k) {
  const double s = std::sqrt(k.delta_E);
  const double half_trace = k.trace_E / 2.0;
  const double big = half_trace + std::copysign(s, half_trace);
  if (big == 0.0) return {0.0, 0.0};
  return {std::ldexp(big, k.exponent_E), std::ldexp(k.det_E / big, k.exponent_E)};
}

// sum_{n>=0} u^n / (2n + 1): atanh(sqrt u)/sqrt u for u > 0, atan(sqrt -u)/sqrt -u
// for u < 0 (|u| < limits::kDoubleEigenvalueSeries).
double atanh_ratio_series(double u) {
  double sum = 0.0, power = 1.0;
  for (int n = 0; n < 14; ++n) {
    sum += power / (2.0 * n + 1.0);
    power *= u;
  }
  return sum;
}

std::string eigenvalue_text(const Matrix2d& L) {
  const Eigenvalues e = eigenvalues(L);
  if (e.im1 == 0.0) {
    if (g6(e.re1) != g6(e.re2)) return g6(e.re1) + " and " + g6(e.re2);
    char text[64];
    std::snprintf(text, sizeof text, "%.17g and %.17g", e.re1, e.re2);
    return text;
  }
  return g6(e.re1) + " +- " + g6(std::abs(e.im1)) + "i";
}

// Why L has no real power (the message of NoRealLogarithm).
std::string no_log_reason(const Matrix2d& L) {
  if (!L.allFinite()) return "the linear part has a non-finite entry";
  const Characteristics k = characteristics(L);
  if (!(k.det > 0.0)) {
    return "the linear part has determinant " + g6(std::ldexp(k.det, 2 * k.exponent)) +
           " <= 0: it is not orientation-preserving, and no continuous motion of affinities "
           "joins it to the identity (Sec. 2.1)";
  }
  if (k.delta == 0.0) {
    return "the linear part has the double negative eigenvalue " + g6(std::ldexp(k.r, k.exponent)) +
           " with a single eigenvector (case G3): it has no real logarithm (Sec. 5.1)";
  }
  return "the linear part has the two distinct negative eigenvalues " + eigenvalue_text(L) +
         " (case G3): it has no real logarithm (Sec. 5.1)";
}

}  // namespace

std::string_view name(RootCase kase) {
  switch (kase) {
    case RootCase::G1:
      return "G1";
    case RootCase::G2:
      return "G2";
    case RootCase::S1:
      return "S1";
    case RootCase::S2:
      return "S2";
    case RootCase::G3:
      return "G3";
  }
  return "?";
}

std::string_view description(RootCase kase) {
  switch (kase) {
    case RootCase::G1:
      return "complex eigenvalues";
    case RootCase::G2:
      return "two positive eigenvalues";
    case RootCase::S1:
      return "eigenvalue 1: translation, shear or one-directional scaling";
    case RootCase::S2:
      return "rotation by pi with uniform scaling";
    case RootCase::G3:
      return "no real logarithm";
  }
  return "?";
}

Eigenvalues eigenvalues(const Matrix2d& L) {
  const Characteristics k = characteristics(L);
  const auto unscaled = [&k](double x) { return std::ldexp(x, k.exponent); };
  if (k.delta < 0.0) {
    const double omega = std::sqrt(-k.delta);
    return {unscaled(k.r), unscaled(omega), unscaled(k.r), -unscaled(omega)};
  }
  const double s = std::sqrt(k.delta);
  const double big = k.r + std::copysign(s, k.r);
  const double small = big == 0.0 ? 0.0 : k.det / big;
  return big >= small ? Eigenvalues{unscaled(big), 0.0, unscaled(small), 0.0}
                      : Eigenvalues{unscaled(small), 0.0, unscaled(big), 0.0};
}

namespace {

// Algorithm 1 (A.5), with the tolerances of limits.hpp where it writes ==.
RootCase select_case(const Characteristics& k) {
  if (!(k.det > 0.0)) return RootCase::G3;
  if (k.delta < 0.0) return RootCase::G1;
  if (k.r < 0.0 && k.n_max <= limits::kHalfTurn * std::abs(k.r)) return RootCase::S2;
  if (k.r < 0.0) return RootCase::G3;  // delta >= 0: real negative eigenvalues
  const auto [mu1, mu2] = real_unit_offsets(k);
  if (std::min(std::abs(mu1), std::abs(mu2)) <= limits::kUnitEigenvalue) return RootCase::S1;
  return RootCase::G2;
}

// log L = c I + k N (N = L - r I), or c I + pi J in S2; gamma = the
// discriminant of log L (its eigenvalues are c +- sqrt(gamma)).
struct LogParts {
  double c;
  Matrix2d M;
  double gamma;
};

LogParts log_parts(const Matrix2d& L, const Characteristics& k, RootCase kase) {
  // c = ln(sqrt(det L)) = ln |lambda| (G1, S2) = (ln lambda1 + ln lambda2)/2 (G2);
  // near the identity from det - 1 = trace E + det E, which has no cancellation there.
  // (On the scaled L^ = 2^-e L: ln det L = ln det L^ + 2 e ln 2.)
  const bool near_identity = k.exponent_E == 0 && std::abs(k.trace_E) + std::abs(k.det_E) < 0.5;
  const double c =
      near_identity ? 0.5 * std::log1p(k.det_minus_one) : 0.5 * std::log(k.det) + k.exponent * std::numbers::ln2;
  if (kase == RootCase::S2) {
    Matrix2d J;
    J << 0.0, -kPi, kPi, 0.0;
    return {c, J, -kPi * kPi};
  }
  // k N is the same for L^ and L: the coefficient scales as 1/2^e, N as 2^e.
  const Matrix2d N = L * std::ldexp(1.0, -k.exponent) - k.r * Matrix2d::Identity();
  double coefficient = 0.0;
  if (k.r > 0.0 && std::abs(k.delta) < limits::kDoubleEigenvalueSeries * k.r * k.r) {
    // Around the double eigenvalue r (delta = 0, G1 meets G2): the limit 1/r.
    coefficient = atanh_ratio_series(k.delta / (k.r * k.r)) / k.r;
  } else if (k.delta < 0.0) {
    // G1, SAM Eq. 18 with atan2 (docs/paper-notes.md N15): theta in (0, pi).
    const double omega = std::sqrt(-k.delta);
    coefficient = std::atan2(omega, k.r) / omega;
  } else {
    // G2 and S1, SAM Eq. 20: y = ln((chi + 1)/(chi - 1))/2 = atanh(s/r), chi = r/s,
    // written ln(lambda1/lambda2)/2 with lambda2 = det/lambda1: atanh(s/r) would
    // lose (lambda1/lambda2) ulps to 1 - s/r when the eigenvalues are far apart.
    const double s = std::sqrt(k.delta);
    const double big = k.r + s;
    coefficient = 0.5 * (std::log(big) - std::log(k.det / big)) / s;
  }
  // gamma = coefficient^2 delta = -theta^2 (G1) or y^2 (G2, S1), formed as
  // +-(coefficient sqrt|delta|)^2: near the S2 boundary (L = -rI plus an
  // off-diagonal entry of 1e-309) delta is subnormal and the coefficient about
  // 1e155, whose square alone overflows (docs/paper-notes.md N15).
  const double root = coefficient * std::sqrt(std::abs(k.delta));
  return {c, coefficient * N, std::copysign(root * root, k.delta)};
}

// (I - L)^-1 on the scaled matrix: 2^-e (one I - L^)^-1 with e = exponent_E,
// one = 2^-e, and det(one I - L^) = det(L^ - one I) = det E^ in 2D.
// Precondition: 1 is not an eigenvalue of L.
Matrix2d inverse_of_identity_minus(const Matrix2d& L, const Characteristics& k) {
  const double scale = std::ldexp(1.0, -k.exponent_E);
  const Matrix2d S = L * scale;
  Matrix2d adjugate;
  adjugate << scale - S(1, 1), S(0, 1), S(1, 0), scale - S(0, 0);
  return adjugate * (scale / k.det_E);
}

}  // namespace

RootCase select_case(const Matrix2d& L) {
  if (!L.allFinite()) return RootCase::G3;
  return select_case(characteristics(L));
}

Matrix2d linear_log(const Matrix2d& L) {
  const RootCase kase = select_case(L);
  if (kase == RootCase::G3) throw NoRealLogarithm(no_log_reason(L), kase);
  const LogParts log = log_parts(L, characteristics(L), kase);
  return log.c * Matrix2d::Identity() + log.M;
}

Matrix2d linear_exp(const Matrix2d& C, double t) {
  const double x = (C(0, 0) + C(1, 1)) / 2.0;
  const double h = (C(0, 0) - C(1, 1)) / 2.0;
  return exp_of_parts(x, C - x * Matrix2d::Identity(), h * h + C(0, 1) * C(1, 0), t);
}

Matrix2d linear_power(const Matrix2d& L, double t) { return AffinePowers(Affine2{L, Vector2d::Zero()}).at(t).L; }

std::optional<Vector2d> fixed_point(const Affine2& A) {
  if (!A.L.allFinite()) return std::nullopt;
  const Characteristics k = characteristics(A.L);
  const RootCase kase = select_case(k);
  if (kase == RootCase::S1) return std::nullopt;
  if (kase == RootCase::G3 && k.det_E == 0.0) return std::nullopt;  // eigenvalue 1 (det <= 0)
  return Vector2d(inverse_of_identity_minus(A.L, k) * A.b);         // (I - L) q = b
}

AffinePowers<Affine2>::AffinePowers(const Affine2& A) : A_(A) {
  if (!A.L.allFinite() || !A.b.allFinite()) {
    throw NoRealLogarithm("the affinity has a non-finite entry", RootCase::G3);
  }
  const Characteristics k = characteristics(A.L);
  case_ = select_case(k);
  if (case_ == RootCase::G3) throw NoRealLogarithm(no_log_reason(A.L), case_);
  const LogParts log = log_parts(A.L, k, case_);
  c_ = log.c;
  M_ = log.M;
  gamma_ = log.gamma;
  C_ = c_ * Matrix2d::Identity() + M_;

  E_ = A.L - Matrix2d::Identity();
  trace_E_ = k.trace_E;
  det_E_ = k.det_E;
  // Spectral radius of E and distance of the nearer eigenvalue of L to 1.
  double radius = 0.0, nearest = 0.0;
  if (case_ == RootCase::S2) {
    radius = nearest = 1.0 - std::ldexp(k.r, k.exponent);  // L = r I, r < 0
  } else if (k.delta < 0.0) {
    // |mu|^2 = det E for mu, conj(mu).
    radius = nearest = std::ldexp(std::sqrt(std::max(k.det_E, 0.0)), k.exponent_E);
  } else {
    std::tie(mu1_, mu2_) = real_unit_offsets(k);
    radius = std::abs(mu1_);
    nearest = std::abs(mu2_);
  }
  if (radius <= limits::kUnitSeriesRadius) {
    translation_ = Translation::unit_series;
  } else if (nearest >= limits::kUnitFixedPointDistance) {
    translation_ = Translation::fixed_point;
  } else {
    translation_ = Translation::eigenvalues;  // real: complex ones have radius == nearest
  }

  // The translation v of log A = [[C, v], [0, 0]]: v = l(L) b with
  // l(lambda) = ln(lambda)/(lambda - 1) (the derivative of g_t at t = 0).
  switch (translation_) {
    case Translation::unit_series: {
      // l(1 + mu) = log1p(mu)/mu = sum_{n>=1} (-1)^{n-1} mu^{n-1}/n.
      double p = 1.0, q = 0.0, g0 = 0.0, g1 = 0.0;  // E^{n-1} = p I + q E
      for (int n = 1; n <= 200; ++n) {
        const double coefficient = (n % 2 == 1 ? 1.0 : -1.0) / n;
        g0 += coefficient * p;
        g1 += coefficient * q;
        const double p_next = -det_E_ * q, q_next = p + trace_E_ * q;
        p = p_next;
        q = q_next;
        if (std::abs(p) + std::abs(q) * (1.0 + E_.norm()) <
            limits::kSeriesTermCutoff * (std::abs(g0) + limits::kTinyScale))
          break;
      }
      log_ratio_ = g0 * Matrix2d::Identity() + g1 * E_;
      break;
    }
    case Translation::fixed_point: {
      inverse_I_minus_L_ = inverse_of_identity_minus(A.L, k);
      log_ratio_ = -C_ * inverse_I_minus_L_;  // C (L - I)^-1
      break;
    }
    case Translation::eigenvalues: {
      const auto l = [](double mu) { return mu == 0.0 ? 1.0 : std::log1p(mu) / mu; };
      log_ratio_ = unit_function(l(mu1_), l(mu2_));
      break;
    }
  }
  v_ = log_ratio_ * A.b;
}

// f(E) = f(mu1) P1 + f(mu2) P2 with the spectral projectors of E = L - I,
// P1 = (E - mu2 I)/(mu1 - mu2), P2 = (E - mu1 I)/(mu2 - mu1) (the eigenvalues
// are real and at least 1/8 apart here). Not g0 I + g1 E: g0 = f(mu1) - g1 mu1
// would cancel when f(mu1) >> f(mu2) (a large t).
Matrix2d AffinePowers<Affine2>::unit_function(double f1, double f2) const {
  const Matrix2d I = Matrix2d::Identity();
  const Matrix2d P1 = (E_ - mu2_ * I) / (mu1_ - mu2_);
  const Matrix2d P2 = (E_ - mu1_ * I) / (mu2_ - mu1_);
  return f1 * P1 + f2 * P2;
}

Matrix2d AffinePowers<Affine2>::power_of_linear(double t) const { return exp_of_parts(c_, M_, gamma_, t); }

Matrix2d AffinePowers<Affine2>::power_minus_identity(double t) const {
  return exp_of_parts_minus_identity(c_, M_, gamma_, t);
}

Affine2 AffinePowers<Affine2>::at_small(double t, const Vector2d& b) const {
  Affine2 result;
  result.L = power_of_linear(t);
  switch (translation_) {
    case Translation::unit_series: {
      // g_t(1 + mu) = ((1 + mu)^t - 1)/mu = sum_{n>=1} C(t, n) mu^{n-1}.
      double p = 1.0, q = 0.0, g0 = 0.0, g1 = 0.0;  // E^{n-1} = p I + q E
      double binomial = t;                          // C(t, 1)
      const double scale = 1.0 + E_.norm();
      for (int n = 1; n <= 400 && binomial != 0.0; ++n) {
        g0 += binomial * p;
        g1 += binomial * q;
        const double p_next = -det_E_ * q, q_next = p + trace_E_ * q;
        p = p_next;
        q = q_next;
        binomial *= (t - n) / (n + 1.0);
        const double term = std::abs(binomial) * (std::abs(p) + std::abs(q) * scale);
        if (term < limits::kSeriesTermCutoff * (std::abs(g0) + std::abs(g1) * scale)) break;
      }
      result.b = (g0 * Matrix2d::Identity() + g1 * E_) * b;
      break;
    }
    case Translation::fixed_point:
      // SAM Eq. 9: A^t(p) = L^t (p - q) + q, so the translation is (I - L^t) q,
      // q = (I - L)^-1 b the fixed point.
      result.b = -power_minus_identity(t) * (inverse_I_minus_L_ * b);
      break;
    case Translation::eigenvalues: {
      const auto g = [t](double mu) { return mu == 0.0 ? t : std::expm1(t * std::log1p(mu)) / mu; };
      result.b = unit_function(g(mu1_), g(mu2_)) * b;
      break;
    }
  }
  return result;
}

Affine2 AffinePowers<Affine2>::at(double t) const { return power_with_translation(t, A_.b); }

Affine2 AffinePowers<Affine2>::power_with_translation(double t, const Vector2d& b) const {
  if (!std::isfinite(t)) {  // no power: callers see a non-finite pose
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return Affine2{Matrix2d::Constant(nan), Vector2d::Constant(nan)};
  }
  if (t == 0.0) return Affine2::identity();
  if (t == 1.0) return Affine2{A_.L, b};
  if (translation_ != Translation::unit_series || std::abs(t) <= limits::kUnitSeriesMaxTime) {
    return at_small(t, b);
  }
  // A^t = (A^{t/2^k})^{2^k}, each factor within the series' range.
  int halvings = 0;
  double step = t;
  while (std::abs(step) > limits::kUnitSeriesMaxTime) {
    step /= 2.0;
    ++halvings;
  }
  Affine2 result = at_small(step, b);
  for (int i = 0; i < halvings; ++i) result = compose(result, result);
  return result;
}

AffinePowers<Affine2> AffinePowers<Affine2>::with_translation(const Vector2d& b) const {
  if (!b.allFinite()) throw NoRealLogarithm("the affinity has a non-finite entry", RootCase::G3);
  AffinePowers powers = *this;
  powers.A_.b = b;
  powers.v_ = log_ratio_ * b;  // as the constructor's v_
  return powers;
}

Affine2 AffinePowers<Affine2>::velocity(double t) const {
  const Affine2 power = at(t);
  return {C_ * power.L, power.L * v_};
}

Affine2 affine_power(const Affine2& A, double t) { return AffinePowers(A).at(t); }

Affine2 log(const Affine2& A) { return AffinePowers(A).log(); }

Affine2 exp(const Affine2& generator) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  H.topLeftCorner<2, 2>() = generator.L;
  H.topRightCorner<2, 1>() = generator.b;
  const Eigen::Matrix3d E = H.exp();  // Eigen's scaling and squaring Pade (MatrixFunctions)
  return {E.topLeftCorner<2, 2>(), E.topRightCorner<2, 1>()};
}

}  // namespace pita
