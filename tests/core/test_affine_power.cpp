// EAR (core/affine_power.hpp): the closed-form log and real powers of 2D
// affinities and the Steady Affine Morph, checked against the properties of
// the SAM paper (Sec. 2.3, 5, 6.1, appendix A) and against Eigen's
// MatrixFunctions module (Schur-Pade log and pow on the 3x3 homogeneous
// matrix) as an independent oracle.
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/affine_power.hpp"
#include "core/limits.hpp"
#include "core/steady_affine_morph.hpp"
#include "support/matrix_functions.hpp"

namespace pita {
namespace {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using Eigen::Vector2d;

Matrix2d mat(double a, double b, double c, double d) {
  Matrix2d L;
  L << a, b, c, d;
  return L;
}
Matrix2d rotation(double angle) { return mat(std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle)); }

Matrix3d homogeneous(const Affine2& A) {
  Matrix3d H = Matrix3d::Identity();
  H.topLeftCorner<2, 2>() = A.L;
  H.topRightCorner<2, 1>() = A.b;
  return H;
}

// |X - Y| / max(|Y|, 1) in the Frobenius norm of the homogeneous matrices.
double relative_error(const Affine2& X, const Affine2& Y) {
  return (homogeneous(X) - homogeneous(Y)).norm() / std::max(homogeneous(Y).norm(), 1.0);
}
double relative_error(const Matrix2d& X, const Matrix2d& Y) { return (X - Y).norm() / std::max(Y.norm(), 1e-300); }

// Eigen's real power of the homogeneous matrix: the independent oracle.
Affine2 eigen_power(const Affine2& A, double t) {
  const Matrix3d P = oracle::pow(homogeneous(A), t);
  Affine2 result;
  result.L = P.topLeftCorner<2, 2>();
  result.b = P.topRightCorner<2, 1>();
  return result;
}

// Near the identity, Eigen's pow loses ~1e-11 (even in long double: its
// Schur-Pade steps are not tuned for it), so there the oracle is the Taylor
// series exp(t log(I + E)) of the homogeneous matrix in long double, with
// log(I + E) = sum (-1)^{n+1} E^n / n (spectral radius of E well below 1).
Affine2 series_power(const Affine2& A, double t) {
  using M3 = Eigen::Matrix<long double, 3, 3>;
  const M3 E = homogeneous(A).cast<long double>() - M3::Identity();
  M3 log = M3::Zero(), power = E;
  for (int n = 1; n < 80; ++n) {
    log += ((n % 2 == 1) ? 1.0L : -1.0L) / n * power;
    power = power * E;
  }
  M3 exp = M3::Identity(), term = M3::Identity();
  for (int n = 1; n < 60; ++n) {
    term = term * (static_cast<long double>(t) * log) / static_cast<long double>(n);
    exp += term;
  }
  const Eigen::Matrix3d P = exp.cast<double>();
  return Affine2{P.topLeftCorner<2, 2>(), P.topRightCorner<2, 1>()};
}

struct Random {
  std::mt19937_64 rng{20261130};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  // An orientation-preserving affinity with a real log: R(a) R(-c) diag(1/s, s) R(c)
  // scaled by e^k (Sec. 5.2), with |a| inside the trapezoid |a| < (1 + s) pi / 2.
  Affine2 steady(double max_scale_log = 2.0) {
    const double s = uniform(0.05, 1.0);
    const double a = uniform(-1.0, 1.0) * (1.0 + s) * kPi / 2.0 * 0.98;
    const double c = uniform(-kPi, kPi);
    const double k = uniform(-max_scale_log, max_scale_log);
    Affine2 A;
    A.L = std::exp(k) * rotation(a) * rotation(-c) * mat(1.0 / s, 0.0, 0.0, s) * rotation(c);
    A.b = Vector2d(uniform(-5.0, 5.0), uniform(-5.0, 5.0));
    return A;
  }
};

// ------------------------------------------------------------ case selection

TEST(SelectCase, TheFiveCasesOfAlgorithmOne) {
  EXPECT_EQ(select_case(rotation(1.0)), RootCase::G1);
  EXPECT_EQ(select_case(2.0 * rotation(3.0)), RootCase::G1);
  EXPECT_EQ(select_case(mat(2.0, 0.3, 0.0, 0.5)), RootCase::G2);
  EXPECT_EQ(select_case(mat(2.0, 1.0, 0.0, 2.0)), RootCase::G2);  // Jordan block, double eigenvalue
  EXPECT_EQ(select_case(3.0 * Matrix2d::Identity()), RootCase::G2);
  EXPECT_EQ(select_case(Matrix2d::Identity()), RootCase::S1);     // translation
  EXPECT_EQ(select_case(mat(1.0, 4.0, 0.0, 1.0)), RootCase::S1);  // shear
  EXPECT_EQ(select_case(mat(1.0, 0.0, 0.0, 3.0)), RootCase::S1);  // one-directional scaling
  EXPECT_EQ(select_case(-2.0 * Matrix2d::Identity()), RootCase::S2);
  // cos/sin of +-pi leave +-1.2e-16 off the diagonal: complex eigenvalues, G1
  // with the principal angle +-(pi - 1.2e-16), not snapped to S2.
  EXPECT_EQ(select_case(rotation(kPi)), RootCase::G1);
  EXPECT_EQ(select_case(rotation(-kPi)), RootCase::G1);
  EXPECT_EQ(select_case(mat(-2.0, 0.0, 0.0, -0.5)), RootCase::G3);
  EXPECT_EQ(select_case(mat(-1.0, 1.0, 0.0, -1.0)), RootCase::G3);  // negative Jordan block
  EXPECT_EQ(select_case(mat(1.0, 0.0, 0.0, -1.0)), RootCase::G3);   // a reflection (det < 0)
}

TEST(SelectCase, HalfTurnThresholdFromBothSides) {
  const double tol = limits::kHalfTurn;
  // Real negative eigenvalues within the tolerance of -rho I: S2 (rounding).
  EXPECT_EQ(select_case(-2.0 * (Matrix2d::Identity() + 0.4 * tol * mat(1, 0, 0, -1))), RootCase::S2);
  EXPECT_EQ(select_case(-2.0 * (Matrix2d::Identity() + 0.4 * tol * mat(0, 1, 0, 0))), RootCase::S2);
  // Beyond it: two distinct negative eigenvalues, or a negative Jordan block, are G3.
  EXPECT_EQ(select_case(-2.0 * (Matrix2d::Identity() + 3.0 * tol * mat(1, 0, 0, -1))), RootCase::G3);
  EXPECT_EQ(select_case(-2.0 * (Matrix2d::Identity() + 3.0 * tol * mat(0, 1, 0, 0))), RootCase::G3);
  // Complex eigenvalues are never snapped: a turn by -(pi - eps) keeps its principal angle.
  EXPECT_EQ(select_case(-2.0 * (Matrix2d::Identity() + 0.4 * tol * mat(0, -1, 1, 0))), RootCase::G1);
  const Matrix2d clockwise = linear_log(rotation(-kPi + 1e-15));
  EXPECT_NEAR(clockwise(1, 0), -(kPi - 1e-15), 1e-15);
  // The discriminant is computed from the entries: a rotation by pi - 1e-9 is G1, not G3
  // (r^2 - det L would round to 0 and then be taken as no SAM; docs/paper-notes.md N15).
  EXPECT_EQ(select_case(rotation(kPi - 1e-9)), RootCase::G1);
}

TEST(SelectCase, UnitEigenvalueThresholdFromBothSides) {
  const double tol = limits::kUnitEigenvalue;
  EXPECT_EQ(select_case(mat(1.0 + 0.5 * tol, 0.0, 0.0, 3.0)), RootCase::S1);
  EXPECT_EQ(select_case(mat(1.0 + 2.0 * tol, 0.0, 0.0, 3.0)), RootCase::G2);
  EXPECT_EQ(select_case(mat(1.0 - 2.0 * tol, 0.0, 0.0, 0.3)), RootCase::G2);
  EXPECT_EQ(select_case(mat(1.0, 5.0, 0.0, 1.0 + 0.5 * tol)), RootCase::S1);
  EXPECT_EQ(select_case(mat(1.0 + 4.0 * tol, 5.0, 0.0, 1.0 + 8.0 * tol)), RootCase::G2);
}

TEST(SelectCase, ComplexOrRealAcrossTheDoubleEigenvalue) {
  // delta = b c for L = [[2, 1], [eps, 2]]: complex for eps < 0, real for eps >= 0.
  EXPECT_EQ(select_case(mat(2.0, 1.0, -1e-300, 2.0)), RootCase::G1);
  EXPECT_EQ(select_case(mat(2.0, 1.0, 0.0, 2.0)), RootCase::G2);
  EXPECT_EQ(select_case(mat(2.0, 1.0, 1e-300, 2.0)), RootCase::G2);
  // With r < 0 the same boundary separates G1 from G3 (no log).
  EXPECT_EQ(select_case(mat(-2.0, 1.0, -1e-12, -2.0)), RootCase::G1);
  EXPECT_EQ(select_case(mat(-2.0, 1.0, 1e-12, -2.0)), RootCase::G3);
}

// Sec. 5.2, SAM Eq. 4: R(a) diag(1/s, s) has a real log iff |a| < acos(-2s/(s^2+1)),
// and the trapezoid |a| < (1 + s) pi / 2 lies inside that region.
TEST(SelectCase, ExistenceRegionIsEquationFour) {
  for (int i = 1; i <= 50; ++i) {
    const double s = i / 50.0;
    const double boundary = std::acos(-2.0 * s / (s * s + 1.0));
    for (const double a : {boundary - 1e-6, boundary + 1e-6}) {
      for (const double sign : {-1.0, 1.0}) {
        const RootCase kase = select_case(rotation(sign * a) * mat(1.0 / s, 0.0, 0.0, s));
        const bool exists = a < boundary;
        if (a > kPi) continue;
        EXPECT_EQ(kase != RootCase::G3, exists) << "s = " << s << ", a = " << sign * a;
      }
    }
    EXPECT_LE((1.0 + s) * kPi / 2.0, boundary + 1e-15) << "trapezoid inside the region at s = " << s;
  }
}

// ---------------------------------------------------------------- log and exp

TEST(LinearLog, ExpOfLogIsL) {
  Random random;
  for (int i = 0; i < 2000; ++i) {
    const Matrix2d L = random.steady(3.0).L;
    const Matrix2d C = linear_log(L);
    EXPECT_LT(relative_error(linear_exp(C), L), 1e-13) << L;
    const Matrix2d root = linear_power(L, 0.5);
    EXPECT_LT(relative_error(Matrix2d(root * root), L), 1e-13) << L;
  }
}

TEST(LinearLog, AgreesWithEigenLog) {
  Random random;
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const Matrix2d L = random.steady(2.0).L;
    const Matrix2d expected = oracle::log(L);
    worst = std::max(worst, (linear_log(L) - expected).norm() / std::max(expected.norm(), 1.0));
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(LinearLog, SpecialCasesHaveTheirClosedForms) {
  // S2: rotation by +pi with scaling 2 (docs/paper-notes.md N15, N23): ln 2 I + pi J.
  EXPECT_LT(relative_error(linear_log(-2.0 * Matrix2d::Identity()), mat(std::log(2.0), -kPi, kPi, std::log(2.0))),
            1e-15);
  // Shear: log [[1, k], [0, 1]] = [[0, k], [0, 0]].
  EXPECT_LT(relative_error(linear_log(mat(1.0, 4.0, 0.0, 1.0)), mat(0.0, 4.0, 0.0, 0.0)), 1e-15);
  // Jordan block: log [[r, 1], [0, r]] = [[ln r, 1/r], [0, ln r]].
  EXPECT_LT(relative_error(linear_log(mat(2.0, 1.0, 0.0, 2.0)), mat(std::log(2.0), 0.5, 0.0, std::log(2.0))), 1e-15);
  // A rotation by theta (G1) has log theta J.
  EXPECT_LT(relative_error(linear_log(rotation(2.5)), mat(0.0, -2.5, 2.5, 0.0)), 1e-15);
  EXPECT_THROW(linear_log(mat(-2.0, 0.0, 0.0, -0.5)), NoRealLogarithm);
}

// Both sides of every switch between formulas agree with Eigen.
TEST(LinearLog, AcrossTheSeriesThresholds) {
  for (const double factor : {0.5, 0.999, 1.001, 2.0}) {
    for (const double sign : {-1.0, 1.0}) {
      // L = [[r, 1], [u r^2, r]]: delta / r^2 = u around kDoubleEigenvalueSeries.
      const double r = 1.7, u = sign * factor * limits::kDoubleEigenvalueSeries;
      const Matrix2d L = mat(r, 1.0, u * r * r, r);
      EXPECT_LT(relative_error(linear_log(L), oracle::log(L)), 1e-13) << "u = " << u;
      EXPECT_LT(relative_error(linear_exp(linear_log(L)), L), 1e-14) << "u = " << u;
    }
  }
  for (const double eps : {1e-16, 1e-12, 1e-8, 1e-4}) {  // nearly Jordan
    const Matrix2d L = mat(2.0, 1.0, eps, 2.0);
    EXPECT_LT(relative_error(linear_log(L), oracle::log(L)), 1e-13) << "eps = " << eps;
  }
}

// --------------------------------------------------------------- powers of A

TEST(AffinePower, IdentityAtZeroAndAAtOne) {
  Random random;
  for (int i = 0; i < 200; ++i) {
    const Affine2 A = random.steady();
    const AffinePowers powers(A);
    EXPECT_EQ(homogeneous(powers.at(0.0)), Matrix3d::Identity());
    EXPECT_EQ(homogeneous(powers.at(1.0)), homogeneous(A));
    // Not only by the shortcut: a hair away, A^t tends to them.
    EXPECT_LT(relative_error(powers.at(1e-14), Affine2::identity()), 1e-12);
    EXPECT_LT(relative_error(powers.at(1.0 - 1e-14), A), 1e-12);
  }
}

TEST(AffinePower, PowersAdd) {
  Random random;
  for (int i = 0; i < 500; ++i) {
    const AffinePowers powers(random.steady(1.5));
    const double s = random.uniform(-1.0, 2.0), t = random.uniform(-1.0, 2.0);
    EXPECT_LT(relative_error(compose(powers.at(s), powers.at(t)), powers.at(s + t)), 1e-12)
        << "s = " << s << ", t = " << t;
  }
}

TEST(AffinePower, FixedPointIsFixed) {
  Random random;
  for (int i = 0; i < 500; ++i) {
    const Affine2 A = random.steady();
    const std::optional<Vector2d> q = fixed_point(A);
    ASSERT_TRUE(q.has_value());
    EXPECT_LT((apply(A, *q) - *q).norm(), 1e-11 * (1.0 + q->norm()));
    const double t = random.uniform(-1.0, 2.0);
    EXPECT_LT((apply(affine_power(A, t), *q) - *q).norm(), 1e-11 * (1.0 + q->norm()));
  }
  EXPECT_FALSE(fixed_point(Affine2{Matrix2d::Identity(), Vector2d(1.0, 2.0)}).has_value());
  EXPECT_FALSE(fixed_point(Affine2{mat(1.0, 0.0, 0.0, 3.0), Vector2d(1.0, 2.0)}).has_value());
}

TEST(AffinePower, AgreesWithEigenPowOnRandomAffinities) {
  Random random;
  double worst = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const Affine2 A = random.steady(2.0);
    const double t = random.uniform(-1.5, 2.5);
    worst = std::max(worst, relative_error(affine_power(A, t), eigen_power(A, t)));
  }
  EXPECT_LT(worst, 1e-12);
}

// The special cases against closed forms written here, and against Eigen.
TEST(AffinePower, PureTranslationMovesAtConstantSpeed) {
  const Affine2 A{Matrix2d::Identity(), Vector2d(3.0, -2.0)};
  for (const double t : {-1.0, 0.25, 0.5, 1.7, 40.0}) {
    const Affine2 P = affine_power(A, t);
    EXPECT_LT(relative_error(P, Affine2{Matrix2d::Identity(), t * A.b}), 1e-15) << t;
  }
}

TEST(AffinePower, ShearAndTranslation) {
  // L = [[1, k], [0, 1]]: L^t = [[1, t k], [0, 1]], translation t b + t(t-1)/2 (L - I) b.
  const double k = 2.5;
  const Affine2 A{mat(1.0, k, 0.0, 1.0), Vector2d(1.0, 3.0)};
  for (const double t : {-0.5, 0.3, 0.5, 2.0, 7.5}) {
    Affine2 expected{mat(1.0, t * k, 0.0, 1.0), t * A.b + t * (t - 1.0) / 2.0 * (A.L - Matrix2d::Identity()) * A.b};
    EXPECT_LT(relative_error(affine_power(A, t), expected), 1e-15) << t;
    EXPECT_LT(relative_error(affine_power(A, t), eigen_power(A, t)), 1e-12) << t;
  }
}

TEST(AffinePower, ScalingAlongOneDirectionWithTranslation) {
  // S1 with a simple eigenvalue 1: diag(1, 3), b = (2, 1):
  // A^t = [diag(1, 3^t) | (2 t, (3^t - 1)/2)] (A.4, case 2).
  const Affine2 A{mat(1.0, 0.0, 0.0, 3.0), Vector2d(2.0, 1.0)};
  for (const double t : {-1.0, 0.2, 0.5, 1.5, 20.0}) {
    const double p = std::pow(3.0, t);
    const Affine2 expected{mat(1.0, 0.0, 0.0, p), Vector2d(2.0 * t, (p - 1.0) / 2.0)};
    EXPECT_LT(relative_error(affine_power(A, t), expected), 1e-14) << t;
  }
}

TEST(AffinePower, HalfTurnWithScaling) {
  // S2: L = -4 I, fixed point q = b / 5: A^t = 4^t R(pi t) about q.
  const Affine2 A{-4.0 * Matrix2d::Identity(), Vector2d(5.0, 10.0)};
  const Vector2d q(1.0, 2.0);
  for (const double t : {0.25, 0.5, 0.75, 1.5}) {
    const Matrix2d L = std::pow(4.0, t) * rotation(kPi * t);
    const Affine2 expected{L, q - L * q};
    EXPECT_LT(relative_error(affine_power(A, t), expected), 1e-14) << t;
  }
  const AffinePowers half(A);
  EXPECT_LT(relative_error(compose(half.at(0.5), half.at(0.5)), A), 1e-14);
}

// Just off the S2 boundary on the complex side (found by fuzz_affine_power):
// L = -r I plus a subnormal top-right entry, so delta ~ -1e-310 and the G1
// coefficient theta/omega ~ 3e155, whose square overflows. log L = c I + M
// with M^2 = -theta^2 I, theta = atan2(omega, r), must stay finite; checked
// through the invariants det M = theta^2, tr L^t = 2 e^{tc} cos(t theta) and
// det L^t = (det L)^t, which do not depend on the huge entries' cancellation.
TEST(AffinePower, HalfTurnBoundaryWithASubnormalEntry) {
  const double r = 0.12401960784313724;
  const Matrix2d L = mat(-r, 1.041639967913776e-309, -0.1240196077860638, -r);
  ASSERT_EQ(select_case(L), RootCase::G1);
  const Affine2 A{L, Vector2d(-r, -r)};
  const AffinePowers powers(A);
  const Matrix2d C = powers.linear_log();
  ASSERT_TRUE(C.allFinite());
  const double c = std::log(r);
  const double theta = kPi;  // atan2(1e-155, -r) rounds to pi
  EXPECT_NEAR(C.trace() / 2.0, c, 1e-14);
  const Matrix2d M = C - c * Matrix2d::Identity();
  EXPECT_NEAR(M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0), theta * theta, 1e-9);
  for (const double t : {5.472998286124e-310, 0.25, 0.5, 1.5, -0.7}) {
    const Affine2 power = powers.at(t);
    ASSERT_TRUE(power.L.allFinite() && power.b.allFinite()) << t;
    const double scale = std::exp(t * c);
    EXPECT_NEAR(power.L.trace(), 2.0 * scale * std::cos(t * theta), 1e-9 * scale) << t;
    EXPECT_NEAR(power.L(0, 0) * power.L(1, 1) - power.L(0, 1) * power.L(1, 0), std::pow(r * r, t), 1e-9 * scale * scale)
        << t;
  }
  EXPECT_LT(relative_error(powers.at(5.472998286124e-310), Affine2::identity()), 1e-12);
}

TEST(AffinePower, JordanBlockAgreesWithEigen) {
  const Affine2 A{mat(2.0, 1.0, 0.0, 2.0), Vector2d(1.0, -1.0)};
  for (const double t : {-0.7, 0.3, 0.5, 1.9}) {
    EXPECT_LT(relative_error(affine_power(A, t), eigen_power(A, t)), 1e-13) << t;
  }
}

// A^t is continuous across each switch of limits.hpp ("EAR"): at both sides
// it agrees with Eigen, and across S1 the two sides agree with each other.
TEST(AffinePower, AcrossTheTranslationFormulaSwitches) {
  std::vector<Affine2> cases;
  for (const double factor : {0.99, 1.01}) {
    const double radius = factor * limits::kUnitSeriesRadius;
    const double near = factor * limits::kUnitFixedPointDistance;
    cases.push_back({mat(1.0 + radius, 0.3, 0.0, 1.0 - radius / 2.0), Vector2d(1.0, 2.0)});
    cases.push_back({mat(1.0 + near, 0.0, 0.0, 2.5), Vector2d(-1.0, 2.0)});
    cases.push_back({mat(1.0 - near, 0.7, 0.0, 0.3), Vector2d(2.0, 1.0)});
    cases.push_back({(1.0 + radius) * rotation(0.1), Vector2d(2.0, 1.0)});
  }
  for (const double eps : {1e-13, 1e-10, 1e-7, 1e-4}) {
    cases.push_back({mat(1.0 + eps, 0.0, 0.0, 2.0), Vector2d(2.0, 1.0)});  // near S1
  }
  for (const Affine2& A : cases) {
    for (const double t : {-0.6, 0.1, 0.5, 0.9, 1.7}) {
      EXPECT_LT(relative_error(affine_power(A, t), eigen_power(A, t)), 1e-12)
          << "A = " << homogeneous(A) << "\nt = " << t;
    }
  }
  // Near the identity (translations, shears, small rotations), against the series.
  std::vector<Affine2> near_identity;
  for (const double eps : {1e-13, 1e-10, 1e-7, 1e-4, 1e-2}) {
    near_identity.push_back({mat(1.0 + eps, 0.5, -eps, 1.0 - eps), Vector2d(2.0, 1.0)});
    near_identity.push_back({(1.0 + eps) * rotation(eps), Vector2d(2.0, 1.0)});
    near_identity.push_back({mat(1.0, 0.1, 0.0, 1.0 + eps), Vector2d(-1.0, 3.0)});
  }
  for (const Affine2& A : near_identity) {
    for (const double t : {-0.6, 0.1, 0.5, 0.9, 1.7}) {
      EXPECT_LT(relative_error(affine_power(A, t), series_power(A, t)), 1e-14)
          << "A = " << homogeneous(A) << "\nt = " << t;
    }
  }
  // Across S1: diag(1 +- 2 kUnitEigenvalue, 3) on either side of the threshold.
  const double tol = limits::kUnitEigenvalue;
  for (const double t : {0.3, 0.5, 2.0}) {
    const Affine2 inside{mat(1.0 + 0.5 * tol, 0.0, 0.0, 3.0), Vector2d(2.0, 1.0)};
    const Affine2 outside{mat(1.0 + 2.0 * tol, 0.0, 0.0, 3.0), Vector2d(2.0, 1.0)};
    EXPECT_LT(relative_error(affine_power(inside, t), affine_power(outside, t)), 1e-11);
  }
}

// Strong stretches: eigenvalues 1e6 and 1e-6 keep their relative accuracy
// (atanh(s/r) and cosh/sinh of a large argument would not).
TEST(AffinePower, StrongStretchesAreExactPerEigenvalue) {
  const Affine2 A{mat(1e6, 0.0, 0.0, 1e-6), Vector2d(1.0, 1.0)};
  for (const double t : {-0.5, 0.5, 1.5}) {
    const Affine2 P = affine_power(A, t);
    const double big = std::pow(1e6, t), small = std::pow(1e-6, t);
    EXPECT_NEAR(P.L(0, 0) / big, 1.0, 1e-14) << t;
    EXPECT_NEAR(P.L(1, 1) / small, 1.0, 1e-14) << t;
    EXPECT_EQ(P.L(0, 1), 0.0);
    EXPECT_EQ(P.L(1, 0), 0.0);
    // Translation (lambda^t - 1)/(lambda - 1) b per axis.
    EXPECT_NEAR(P.b(0) / ((big - 1.0) / (1e6 - 1.0)), 1.0, 1e-14) << t;
    EXPECT_NEAR(P.b(1) / ((small - 1.0) / (1e-6 - 1.0)), 1.0, 1e-14) << t;
  }
}

// Far extrapolation keeps every entry's relative accuracy: a contraction
// diag(0.5, 0.25) at t = +-100 (cosh - sinh would lose all digits of the small
// eigenvalue's direction, and the translation would cancel), and a
// one-directional scaling with eigenvalue 1 at t = 60 (its divided difference
// would cancel).
TEST(AffinePower, FarExtrapolationIsExactPerEntry) {
  const Affine2 contraction{mat(0.5, 0.0, 0.0, 0.25), Vector2d(1.0, 1.0)};
  for (const double t : {-100.0, -30.0, 60.0, 110.0, 300.0}) {
    const Affine2 P = affine_power(contraction, t);
    const double x = std::pow(0.5, t), y = std::pow(0.25, t);
    EXPECT_NEAR(P.L(0, 0) / x, 1.0, 1e-13) << t;
    EXPECT_NEAR(P.L(1, 1) / y, 1.0, 1e-13) << t;
    EXPECT_NEAR(P.b(0) / ((x - 1.0) / (0.5 - 1.0)), 1.0, 1e-13) << t;  // -> the fixed point 2
    EXPECT_NEAR(P.b(1) / ((y - 1.0) / (0.25 - 1.0)), 1.0, 1e-13) << t;
  }
  const Affine2 scaling{mat(1.0, 0.0, 0.0, 3.0), Vector2d(1.0, 2.0)};
  for (const double t : {-40.0, 60.0}) {
    const Affine2 P = affine_power(scaling, t);
    EXPECT_NEAR(P.b(0) / t, 1.0, 1e-13) << t;
    EXPECT_NEAR(P.b(1) / (std::pow(3.0, t) - 1.0), 1.0, 1e-13) << t;
  }
  // A non-finite time gives a non-finite pose (never a hang or a wrong number).
  const AffinePowers near_identity(Affine2{Matrix2d::Identity(), Vector2d(1.0, 0.0)});
  EXPECT_FALSE(near_identity.at(std::numeric_limits<double>::infinity()).b.allFinite());
  EXPECT_FALSE(near_identity.at(std::nan("")).b.allFinite());
}

// Entries of 1e+-200 (C o B^-1 of poses at the scene limits 1e+-100): no
// determinant over- or underflows on the way.
TEST(AffinePower, ExtremeScales) {
  for (const double scale : {1e-200, 1e-150, 1e150, 1e200}) {
    const Affine2 A{scale * rotation(0.5), Vector2d(1.0, 2.0)};
    const AffinePowers powers(A);
    EXPECT_EQ(powers.root_case(), RootCase::G1) << scale;
    const Affine2 half = powers.at(0.5);
    // ln det L ~ +-920 carries ~1e-13 of absolute rounding into the scale.
    // Norms of x - y and y divided by y's largest entry (no over- or underflow at 1e+-200).
    // Not stableNorm: Eigen 3.4's stableNorm of a 2x2 matrix returns 0 under NDEBUG (and
    // fails an assertion without it), which made these checks vacuous.
    const auto relative = [](const auto& x, const auto& y) {
      using Value = std::decay_t<decltype(y)>;
      const double size = y.cwiseAbs().maxCoeff();
      const Value difference = (x - y) / size, unit = y / size;
      return difference.norm() / unit.norm();
    };
    EXPECT_LT(relative(half.L, Matrix2d(std::sqrt(scale) * rotation(0.25))), 1e-13) << scale;
    const Affine2 square = compose(half, half);
    EXPECT_LT(relative(square.L, A.L), 1e-13) << scale;
    EXPECT_LT(relative(square.b, A.b), 1e-13) << scale;
    const std::optional<Vector2d> q = fixed_point(A);
    ASSERT_TRUE(q.has_value());
    EXPECT_LT((apply(A, *q) - *q).norm(), 1e-13 * (1.0 + q->norm() + scale * q->norm())) << scale;
  }
  EXPECT_EQ(select_case(mat(-1e200, 0.0, 0.0, -1e200)), RootCase::S2);
  EXPECT_EQ(select_case(mat(-2e-200, 0.0, 0.0, -1e-200)), RootCase::G3);
  EXPECT_EQ(select_case(mat(1e200, 0.0, 0.0, 1.0)), RootCase::S1);
}

TEST(AffinePower, LargeTimesThroughSquaring) {
  const Affine2 A{mat(1.01, 0.2, 0.0, 0.99), Vector2d(1.0, 2.0)};
  for (const double t : {17.0, 100.5, -40.25}) {
    EXPECT_LT(relative_error(affine_power(A, t), eigen_power(A, t)), 1e-11) << t;
  }
}

TEST(AffinePower, HomogeneousLogAgreesWithEigen) {
  Random random;
  for (int i = 0; i < 300; ++i) {
    const Affine2 A = random.steady(1.5);
    const AffinePowers powers(A);
    Matrix3d X = Matrix3d::Zero();
    X.topLeftCorner<2, 2>() = powers.linear_log();
    X.topRightCorner<2, 1>() = powers.velocity_translation();
    const Matrix3d expected = oracle::log(homogeneous(A));
    EXPECT_LT((X - expected).norm() / std::max(expected.norm(), 1.0), 1e-12);
  }
  const AffinePowers shear(Affine2{mat(1.0, 2.0, 0.0, 1.0), Vector2d(1.0, 1.0)});
  // log of [[1, 2, 1], [0, 1, 1], [0, 0, 1]]: N - N^2/2 with N = H - I.
  EXPECT_LT((shear.velocity_translation() - Vector2d(0.0, 1.0)).norm() +
                (shear.linear_log() - mat(0.0, 2.0, 0.0, 0.0)).norm(),
            1e-15);
}

// The identities on each case and on both sides of each boundary.
TEST(AffinePower, IdentitiesOnEveryCaseAndBoundary) {
  const double half = limits::kHalfTurn, unit = limits::kUnitEigenvalue;
  const std::vector<Matrix2d> linear = {
      rotation(1.0),
      2.0 * rotation(2.9),
      rotation(kPi - 1e-9),  // G1
      mat(2.0, 0.3, 0.0, 0.5),
      mat(2.0, 1.0, 0.0, 2.0),
      3.0 * Matrix2d::Identity(),  // G2
      mat(2.0, 1.0, 1e-9, 2.0),
      mat(2.0, 1.0, -1e-9, 2.0),  // G1 | G2
      Matrix2d::Identity(),
      mat(1.0, 4.0, 0.0, 1.0),
      mat(1.0, 0.0, 0.0, 3.0),  // S1
      mat(1.0 + 0.5 * unit, 0.0, 0.0, 3.0),
      mat(1.0 + 2.0 * unit, 0.0, 0.0, 3.0),  // S1 | G2
      -2.0 * Matrix2d::Identity(),
      rotation(kPi),
      rotation(-kPi),                                                 // S2, G1 at +-pi
      -2.0 * (Matrix2d::Identity() + 0.4 * half * mat(1, 0, 0, -1)),  // S2 | G3
      -2.0 * (Matrix2d::Identity() + 3.0 * half * mat(0, -1, 1, 0)),  // S2 | G1
      mat(1e6, 0.0, 0.0, 1e-6),
      rotation(0.3) * mat(1e3, 0.0, 0.0, 1e-3) * rotation(-0.3),  // stretches
      mat(-2.0, 1.0, -1e-12, -2.0),                               // G1 | G3
  };
  for (const Matrix2d& L : linear) {
    const Affine2 A{L, Vector2d(1.5, -0.5)};
    const AffinePowers powers(A);
    SCOPED_TRACE(::testing::Message() << "L = " << L << ", case " << name(powers.root_case()));
    // Errors scale with the size of the log (~3e6 for the near-Jordan G1 | G3 case: it is
    // ill-conditioned, not inaccurate).
    const double k = 1.0 + powers.linear_log().norm();
    // S2 snaps L within kHalfTurn of -rho I onto it: A^1 = A is then exact only to that.
    const double snap = powers.root_case() == RootCase::S2 ? 2.0 * half : 0.0;
    EXPECT_LT(relative_error(linear_exp(linear_log(L)), L), 1e-14 * k + snap);
    EXPECT_EQ(homogeneous(powers.at(0.0)), Matrix3d::Identity());
    EXPECT_LT(relative_error(powers.at(1.0 - 1e-15), A), 1e-13 * k);
    for (const auto& [s, t] : {std::pair{0.3, 0.4}, std::pair{-0.5, 1.25}, std::pair{0.5, 0.5}}) {
      EXPECT_LT(relative_error(compose(powers.at(s), powers.at(t)), powers.at(s + t)), 1e-14 * k + snap)
          << "s = " << s << ", t = " << t;
    }
    if (const std::optional<Vector2d> q = fixed_point(A)) {
      EXPECT_LT((apply(powers.at(0.37), *q) - *q).norm(), 1e-14 * k * (1.0 + q->norm()));
    } else {
      EXPECT_EQ(powers.root_case(), RootCase::S1);
    }
  }
}

TEST(AffinePower, NoRealPowerIsRefused) {
  const Affine2 A{mat(-2.0, 0.0, 0.0, -0.5), Vector2d(1.0, 0.0)};
  try {
    AffinePowers powers(A);
    FAIL() << "G3 accepted";
  } catch (const NoRealLogarithm& error) {
    EXPECT_EQ(error.root_case(), RootCase::G3);
    EXPECT_NE(std::string(error.what()).find("no real logarithm"), std::string::npos) << error.what();
  }
  EXPECT_THROW(AffinePowers(Affine2{mat(1.0, 0.0, 0.0, -1.0), Vector2d::Zero()}), NoRealLogarithm);
  EXPECT_THROW(AffinePowers(Affine2{mat(NAN, 0.0, 0.0, 1.0), Vector2d::Zero()}), NoRealLogarithm);
}

// with_translation(b) is AffinePowers(Affine2{L, b}) bit for bit, in each way
// of computing the translation (series near I, fixed point, eigenvalues).
TEST(AffinePower, WithTranslationIsAFreshConstruction) {
  const Vector2d b(-0.7, 2.5);
  for (const Matrix2d& L : {Matrix2d(mat(1.05, 0.02, -0.01, 0.97)), Matrix2d(2.0 * rotation(0.8)),
                            Matrix2d(mat(1.1, 0.3, 0.0, 3.0)), Matrix2d(mat(1.0, 2.0, 0.0, 1.0))}) {
    const AffinePowers fresh(Affine2{L, b});
    const AffinePowers moved = AffinePowers(Affine2{L, Vector2d(4.0, -1.0)}).with_translation(b);
    EXPECT_EQ(moved.affinity().b, b);
    EXPECT_EQ(moved.log().L, fresh.log().L);
    EXPECT_EQ(moved.log().b, fresh.log().b);
    for (const double t : {-1.3, 0.25, 0.5, 2.0, 7.0}) {
      EXPECT_EQ(moved.at(t).L, fresh.at(t).L) << t;
      EXPECT_EQ(moved.at(t).b, fresh.at(t).b) << t;
      EXPECT_EQ(moved.velocity(t).b, fresh.velocity(t).b) << t;
    }
  }
  EXPECT_THROW((void)AffinePowers(Affine2::identity()).with_translation(Vector2d(NAN, 0.0)), NoRealLogarithm);
}

// velocity(t) = d/dt A^t = log(A) A^t (central differences).
TEST(AffinePower, VelocityIsTheDerivative) {
  const AffinePowers powers(Affine2{1.5 * rotation(0.6), Vector2d(1.0, -2.0)});
  const double h = 1e-6;
  for (const double t : {-0.5, 0.0, 0.4, 1.0, 2.5}) {
    const Affine2 before = powers.at(t - h), after = powers.at(t + h), rate = powers.velocity(t);
    EXPECT_LT((rate.L - (after.L - before.L) / (2.0 * h)).norm(), 1e-7) << t;
    EXPECT_LT((rate.b - (after.b - before.b) / (2.0 * h)).norm(), 1e-7) << t;
  }
  EXPECT_EQ(powers.velocity(0.0).L, powers.log().L);
  EXPECT_EQ(powers.velocity(0.0).b, powers.log().b);
}

// -------------------------------------------------------- Steady Affine Morph

TEST(SteadyAffineMorph, InterpolatesThePoses) {
  Random random;
  for (int i = 0; i < 200; ++i) {
    const Affine2 B = random.steady(), A = random.steady();
    const Affine2 C = compose(A, B);
    const SteadyAffineMorph sam(B, C);
    EXPECT_LT(relative_error(sam.at(0.0), B), 1e-15);
    EXPECT_LT(relative_error(sam.at(1.0), C), 1e-12);
  }
}

// Sec. 2.3 (2): a change of coordinates T commutes with the SAM, and so does
// a change of the shape's own frame S.
TEST(SteadyAffineMorph, AffineInvariant) {
  Random random;
  for (int i = 0; i < 300; ++i) {
    const Affine2 B = random.steady(), C = compose(random.steady(1.0), B);
    Affine2 T = random.steady(1.0), S = random.steady(1.0);
    const double t = random.uniform(-0.5, 1.5);
    const Affine2 base = steady_affine_morph(B, C, t);
    EXPECT_LT(relative_error(steady_affine_morph(compose(T, B), compose(T, C), t), compose(T, base)), 1e-11);
    EXPECT_LT(relative_error(steady_affine_morph(compose(B, S), compose(C, S), t), compose(base, S)), 1e-11);
  }
}

// Sec. 2.3 (3): swapping the poses reverses the motion.
TEST(SteadyAffineMorph, Reversible) {
  Random random;
  for (int i = 0; i < 300; ++i) {
    const Affine2 B = random.steady(), C = compose(random.steady(1.0), B);
    const double t = random.uniform(0.0, 1.0);
    EXPECT_LT(relative_error(steady_affine_morph(B, C, t), steady_affine_morph(C, B, 1.0 - t)), 1e-11);
  }
}

// Sec. 6.1: the velocity in the local frame, F(t)^-1 F'(t), is constant, and
// so is the global one, F'(t) F(t)^-1 = log A (finite differences).
TEST(SteadyAffineMorph, VelocityConstantInTheLocalFrame) {
  Random random;
  const double h = 1e-5;
  for (int i = 0; i < 100; ++i) {
    const Affine2 B = random.steady(1.0), C = compose(random.steady(1.0), B);
    const SteadyAffineMorph sam(B, C);
    const auto local = [&](double t) {
      const Matrix3d derivative = (homogeneous(sam.at(t + h)) - homogeneous(sam.at(t - h))) / (2.0 * h);
      return Matrix3d(homogeneous(sam.at(t)).inverse() * derivative);
    };
    const auto global = [&](double t) {
      const Matrix3d derivative = (homogeneous(sam.at(t + h)) - homogeneous(sam.at(t - h))) / (2.0 * h);
      return Matrix3d(derivative * homogeneous(sam.at(t)).inverse());
    };
    const Matrix3d local0 = local(0.0), global0 = global(0.0);
    for (const double t : {0.25, 0.5, 0.75, 1.0}) {
      EXPECT_LT((local(t) - local0).norm(), 1e-7 * (1.0 + local0.norm()));
      EXPECT_LT((global(t) - global0).norm(), 1e-7 * (1.0 + global0.norm()));
    }
    // An unsteady motion fails the same check: linear interpolation of the matrices.
    const auto linear = [&](double t) { return Matrix3d((1.0 - t) * homogeneous(B) + t * homogeneous(C)); };
    const auto linear_local = [&](double t) {
      return Matrix3d(linear(t).inverse() * (linear(t + h) - linear(t - h)) / (2.0 * h));
    };
    EXPECT_GT((linear_local(0.75) - linear_local(0.25)).norm(), 1e-4 * (1.0 + linear_local(0.25).norm()));
  }
}

// From a pose 1e-50 the size of the other: A = C o B^-1 has a huge
// translation, which the SAM's translation b_B + g_u(L)(b_C - b_B) never forms.
// Closed form for B = [s R(theta) | b_B], C = identity: L_A = R(-theta)/s, and
// in complex numbers the translation is (1 - g_u(lambda)) b_B, lambda = e^{-i theta}/s.
TEST(SteadyAffineMorph, FromATinyPose) {
  for (const double s : {1e-8, 1e-50}) {
    const double theta = 0.4;
    const Affine2 B{s * rotation(theta), Vector2d(3.0, 4.0)};
    const SteadyAffineMorph sam(B, Affine2::identity());
    for (const double u : {0.5, 1.5}) {
      const std::complex<double> lambda = std::polar(1.0 / s, -theta);
      const std::complex<double> g = (std::pow(lambda, u) - 1.0) / (lambda - 1.0);
      const std::complex<double> b = (1.0 - g) * std::complex<double>(3.0, 4.0);
      const Affine2 pose = sam.at(u);
      EXPECT_LT(std::abs(std::complex<double>(pose.b.x(), pose.b.y()) - b), 1e-13 * std::abs(b))
          << "s = " << s << ", u = " << u;
    }
  }
}

TEST(SteadyAffineMorph, NoSamBetweenPosesIsSaidClearly) {
  const Affine2 B{rotation(0.3), Vector2d(1.0, 0.0)};
  const Affine2 C = compose(Affine2{mat(-2.0, 0.0, 0.0, -0.5), Vector2d(0.0, 1.0)}, B);
  try {
    SteadyAffineMorph sam(B, C);
    FAIL() << "no SAM expected";
  } catch (const NoRealLogarithm& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("no SAM exists between these poses: ", 0), 0u) << message;
    EXPECT_NE(message.find("middle pose"), std::string::npos) << message;
  }
}

TEST(AffineVerbs, ExpOfLogIsTheAffinityAndExpOfTLogIsItsPower) {
  // log by EAR's closed forms, exp by Eigen's Pade on the homogeneous matrix:
  // two independent computations that must agree.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    Affine2 A;
    A.L << 1.0 + u(rng), u(rng), u(rng), 1.0 + u(rng);
    A.b << 3.0 * u(rng), 3.0 * u(rng);
    if (select_case(A.L) == RootCase::G3) continue;
    const Affine2 G = log(A);
    const Affine2 back = exp(G);
    EXPECT_LT((back.L - A.L).norm(), 1e-12 * (1.0 + A.L.norm())) << i;
    EXPECT_LT((back.b - A.b).norm(), 1e-12 * (1.0 + A.b.norm())) << i;
    for (const double t : {-0.5, 0.3, 1.7}) {
      const Affine2 power = pow(A, t), via = exp(Affine2{t * G.L, t * G.b});
      EXPECT_LT((power.L - via.L).norm(), 1e-11 * (1.0 + power.L.norm())) << i << " t " << t;
      EXPECT_LT((power.b - via.b).norm(), 1e-11 * (1.0 + power.b.norm())) << i << " t " << t;
    }
    // compose and inverse are the group's: A o A^-1 = identity.
    const Affine2 one = compose(A, inverse(A));
    EXPECT_LT((one.L - Matrix2d::Identity()).norm(), 1e-12);
    ++checked;
  }
  EXPECT_GT(checked, 100);
  Affine2 half_turn;
  half_turn.L << -1.0, 0.0, 0.0, -2.0;  // distinct negative eigenvalues: G3
  EXPECT_THROW(log(half_turn), NoRealLogarithm);
}

}  // namespace
}  // namespace pita
