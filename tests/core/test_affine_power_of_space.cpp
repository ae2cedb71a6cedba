// EAR in 3D (core/affine_power_of_space.hpp, SAM paper appendix A.6): log and real
// powers of 3D affinities, checked by their properties (exp(log A) = A,
// A^s A^t = A^{s+t}), by closed forms for each singular sub-case of A.6, by
// the 2D EAR on embedded planar affinities, and against Eigen's
// MatrixFunctions (Schur-Pade pow on the 4x4 homogeneous matrix) as an
// independent oracle.
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/affine_power.hpp"
#include "core/affine_power_of_space.hpp"
#include "core/limits.hpp"
#include "support/matrix_functions.hpp"
#include "support/sanitizers.hpp"

namespace pita {
namespace {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using Eigen::Matrix4d;
using Eigen::Vector2d;
using Eigen::Vector3d;

// |X - Y|_F / max(|Y|_F, 1) on the homogeneous matrices.
double relative_error(const Affine3& X, const Affine3& Y) {
  return (homogeneous(X) - homogeneous(Y)).norm() / std::max(homogeneous(Y).norm(), 1.0);
}

// Where they differ: the largest entry difference of the 3x4 matrices.
std::string where(const Affine3& X, const Affine3& Y) {
  const Eigen::Matrix<double, 3, 4> D = (homogeneous(X) - homogeneous(Y)).topRows<3>();
  Eigen::Index r = 0, c = 0;
  const double largest = D.cwiseAbs().maxCoeff(&r, &c);
  return "entry (" + std::to_string(r) + ", " + std::to_string(c) + ") differs by " + std::to_string(largest) +
         " (got " + std::to_string(homogeneous(X)(r, c)) + ", expected " + std::to_string(homogeneous(Y)(r, c)) + ")";
}

#define EXPECT_AFFINE_NEAR(X, Y, tolerance) EXPECT_LE(relative_error((X), (Y)), (tolerance)) << where((X), (Y))

// The rotation by angle about the unit axis u (Rodrigues).
Matrix3d rotation(const Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

Affine3 exp_long_double(const Affine3& generator) {
  Eigen::Matrix<long double, 4, 4> H = Eigen::Matrix<long double, 4, 4>::Zero();
  H.topLeftCorner<3, 3>() = generator.L.cast<long double>();
  H.topRightCorner<3, 1>() = generator.b.cast<long double>();
  return affine3_of(Matrix4d(oracle::exp(H).cast<double>()));
}

Affine3 eigen_power(const Affine3& A, double t) { return affine3_of(oracle::pow(homogeneous(A), t)); }

// Random affinities with a real log: L = e^k V D V^-1, D a positive diagonal
// or a positive eigenvalue beside a rotation-scaling (angle within (-pi, pi)),
// V with condition number up to about kappa_V, eigenvalue ratios up to
// `spread`.
struct RandomAffinities {
  std::mt19937_64 rng;
  explicit RandomAffinities(unsigned seed) : rng(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  // Three draws in a fixed order: the order in which a constructor's
  // arguments are evaluated is unspecified (gcc goes right to left, clang
  // left to right), and the cases must be the same under both compilers.
  Vector3d uniform3(double a, double b) {
    const double x = uniform(a, b);
    const double y = uniform(a, b);
    const double z = uniform(a, b);
    return {x, y, z};
  }

  // A uniformly random rotation from this generator (Eigen's UnitRandom
  // draws from std::rand, whose state other tests change: the cases would
  // depend on the order the tests run in).
  Matrix3d random_rotation() {
    std::normal_distribution<double> normal;
    const double w = normal(rng);
    const double x = normal(rng);
    const double y = normal(rng);
    const double z = normal(rng);
    Eigen::Quaterniond q(w, x, y, z);
    return q.normalized().toRotationMatrix();
  }

  Matrix3d conditioned_basis(double kappa) {
    const Matrix3d U = random_rotation();
    const Matrix3d W = random_rotation();
    const double e = std::log(kappa);
    const Vector3d s(1.0, std::exp(-e * uniform(0.0, 1.0)), std::exp(-e));
    return U * s.asDiagonal() * W.transpose();
  }

  // extreme: the eigenvalue ratio is exactly `spread` (its two ends taken),
  // so that the condition number of L reaches towards spread kappa_V^2.
  Affine3 next(double spread, double kappa_V, bool extreme = false) {
    const double half = std::log(spread) / 2.0;
    const double sign = uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    Matrix3d D = Matrix3d::Zero();
    if (uniform(0.0, 1.0) < 0.5) {
      D.diagonal() = uniform3(-half, half).array().exp().matrix();
      if (extreme) {
        D(0, 0) = std::exp(sign * half);
        D(2, 2) = std::exp(-sign * half);
      }
    } else {
      const double rho = std::exp(extreme ? -sign * half : uniform(-half, half));
      const double angle = uniform(-0.97 * kPi, 0.97 * kPi);
      D(0, 0) = std::exp(extreme ? sign * half : uniform(-half, half));
      D.block<2, 2>(1, 1) = rho * Eigen::Rotation2Dd(angle).toRotationMatrix();
    }
    const Matrix3d V = conditioned_basis(kappa_V);
    Affine3 A;
    A.L = V * D * V.inverse();
    A.b = uniform3(-5, 5);
    return A;
  }
};

// |L|_F |L^-1|_F: between the 2-norm condition number and 3 times it.
double condition_number(const Matrix3d& L) { return L.norm() * L.inverse().norm(); }

// ------------------------------------------------------------ properties

TEST(AffinePower3, IdentityAtZeroAndAAtOne) {
  RandomAffinities random(1);
  for (int i = 0; i < 50; ++i) {
    const Affine3 A = random.next(1e4, 10.0);
    const AffinePowers powers(A);
    EXPECT_EQ(homogeneous(powers.at(0.0)), Matrix4d::Identity());
    EXPECT_EQ(homogeneous(powers.at(1.0)), homogeneous(A));
  }
}

// How far exp(log A) lands from A, for our log and for two references: the
// correctly rounded log (Eigen's log in long double, rounded to double: the
// floor of any algorithm that returns a double log) and Eigen's double
// Schur-Pade log. exp in long double, so that the errors are the logs'.
struct LogErrors {
  double ours, floor, eigen;
};
LogErrors log_errors(const AffinePowers<Affine3>& powers) {
  const Affine3& A = powers.affinity();
  const Eigen::Matrix<long double, 4, 4> H = homogeneous(A).cast<long double>();
  const Matrix4d rounded = oracle::log(H).cast<double>();
  return {relative_error(exp_long_double(powers.log()), A), relative_error(exp_long_double(affine3_of(rounded)), A),
          relative_error(exp_long_double(affine3_of(oracle::log(homogeneous(A)))), A)};
}

// 1e-12 as the issue asks, or within 8 times the floor where conditioning
// puts even the correctly rounded log near 1e-12 (case 178 of these: the
// rounded log itself is 2.1e-12 from A, Eigen's 1.7e-12; ours now below
// 1e-12 there too, after the refinement).
// docs/paper-notes.md N58 has the measurements.
TEST(AffinePower3, ExpOfLogAndPowersAddOnIllConditionedAffinities) {
  // Condition numbers of L up to about 3e7 (eigenvalue ratios up to 1e4, half
  // of the cases at exactly 1e4, and a basis of condition up to 1e2); every
  // case of the split among them.
  RandomAffinities random(2);
  double worst_condition = 0.0, worst_exp = 0.0, worst_add = 0.0, worst_half = 0.0;
  for (int i = 0; i < 400; ++i) {
    const Affine3 A = random.next(1e4, 1e2, i % 2 == 0);
    const double condition = condition_number(A.L);
    worst_condition = std::max(worst_condition, condition);
    const AffinePowers powers(A);
    const LogErrors e = log_errors(powers);
    worst_exp = std::max(worst_exp, e.ours);
    EXPECT_LE(e.ours, std::max(1e-12, 8.0 * e.floor))
        << "case " << i << " condition " << condition << " (correctly rounded log: " << e.floor
        << ", Eigen's: " << e.eigen << ")";
    const double s = random.uniform(0.0, 1.0), t = random.uniform(0.0, 1.0);
    const Affine3 sum = powers.at(s + t);
    const double a = relative_error(compose(powers.at(s), powers.at(t)), sum);
    worst_add = std::max(worst_add, a);
    EXPECT_LE(a, 1e-12) << "case " << i << " s " << s << " t " << t;
    const Affine3 half = powers.at(0.5);
    const double h = relative_error(compose(half, half), A);
    worst_half = std::max(worst_half, h);
    EXPECT_LE(h, 1e-12) << "case " << i;
  }
  EXPECT_GE(worst_condition, 1e7);  // the range asked for is covered
  std::printf("condition up to %.2g: exp(log A) %.2g, A^s A^t %.2g, A^1/2 A^1/2 %.2g\n", worst_condition, worst_exp,
              worst_add, worst_half);
}

// Condition numbers up to 1e8 (eigenvalue ratio 1e4, basis condition 2e2).
// The split alone misses 1e-12 here on 7 of these 200 cases (worst 4.1e-12,
// blocks far from normal with eigenvalues 1e4 apart), as does Eigen's
// Schur-Pade log (3.8e-12); log()'s Newton steps in extended precision (N58,
// "refinement") bring every case to 1e-12 or to 8 times the floor where even
// the correctly rounded log misses 1e-12.
TEST(AffinePower3, ExpOfLogHoldsOneE12NearConditionOneE8) {
  RandomAffinities random(6);
  double worst_condition = 0.0, worst_ours = 0.0, worst_eigen = 0.0;
  int refined = 0;
  constexpr int kCases = 200;
  for (int i = 0; i < kCases; ++i) {
    const Affine3 A = random.next(1e4, 2e2, true);
    const double condition = condition_number(A.L);
    worst_condition = std::max(worst_condition, condition);
    const AffinePowers powers(A);
    const LogErrors e = log_errors(powers);
    worst_ours = std::max(worst_ours, e.ours);
    worst_eigen = std::max(worst_eigen, e.eigen);
    EXPECT_LE(e.ours, std::max(1e-12, 8.0 * e.floor))
        << "case " << i << " condition " << condition << " (correctly rounded log: " << e.floor
        << ", Eigen's: " << e.eigen << ")";
    refined += homogeneous(powers.log()) != homogeneous(powers.split_log()) ? 1 : 0;
    const Affine3 half = powers.at(0.5);
    EXPECT_LE(relative_error(compose(half, half), A), 1e-11) << "case " << i;
  }
  EXPECT_GE(worst_condition, 5e7);
  EXPECT_GT(refined, 0);  // the refinement is what is checked here
  std::printf("condition up to %.2g: exp(log A) %.2g (%d of %d refined; Eigen's log: %.2g)\n", worst_condition,
              worst_ours, refined, kCases, worst_eigen);
}

// A thousand fresh cases of the same kind: 1e-12 literally on at least 99%
// of them, and every one within max(1e-12, 8 times the floor) (measured: 0
// beyond 1e-12 here; 5 of 3000 on seeds 7-9, N58).
TEST(AffinePower3, ExpOfLogOnAThousandCasesNearConditionOneE8) {
  RandomAffinities random(7);
  const int kCases = test::sample_size(1000, 200);  // accuracy, not memory: all of them in Release
  int beyond = 0;
  double worst = 0.0;
  for (int i = 0; i < kCases; ++i) {
    const Affine3 A = random.next(1e4, 2e2, true);
    const LogErrors e = log_errors(AffinePowers(A));
    worst = std::max(worst, e.ours);
    beyond += e.ours > 1e-12 ? 1 : 0;
    EXPECT_LE(e.ours, std::max(1e-12, 8.0 * e.floor)) << "case " << i << " (correctly rounded log: " << e.floor << ")";
  }
  EXPECT_LE(beyond, kCases / 100);
  std::printf("%d cases: exp(log A) worst %.2g, %d beyond 1e-12\n", kCases, worst, beyond);
}

// The refinement never moves the log to another branch: near a half turn
// the Frechet derivative of exp is nearly singular, and the log must stay the
// split's (the rotation by pi - e keeps its angle).
TEST(AffinePower3, RefinedLogStaysOnTheSplitsBranch) {
  for (const double e : {1e-9, 1e-6, 1e-3}) {
    // A rotation by pi - e seen in a sheared basis (not normal).
    Matrix3d S;
    S << 1.0, 2.0, 0.0, 0.0, 1.0, 3.0, 0.5, 0.0, 1.0;
    Affine3 A;
    A.L = S * rotation(Vector3d(1.0, 2.0, 3.0), kPi - e) * S.inverse();
    A.b = Vector3d(1.0, -2.0, 0.5);
    const AffinePowers powers(A);
    const Affine3 split = powers.split_log();
    EXPECT_LE(relative_error(powers.log(), split), 1e-6) << "e " << e;
    EXPECT_LE(relative_error(exp_long_double(powers.log()), A), std::max(1e-12, 4e-16 / e)) << "e " << e;
    // Its angle is still pi - e: S^-1 log L S is that rotation's generator.
    const Matrix3d generator = S.inverse() * powers.log().L * S;
    EXPECT_NEAR(Eigen::Vector3d(generator(2, 1), generator(0, 2), generator(1, 0)).norm(), kPi - e, 1e-6) << "e " << e;
  }
}

// Against Eigen's pow (Schur-Pade on the 4x4 homogeneous matrix) in long
// double, rounded to double: an independent computation with 11 more bits.
// Eigen's pow in double is no reference at 1e-12: on these cases it is up to
// 1.4e-10 away from its long-double self (case 130, t = -0.031), while we
// stay within 1.2e-13 (oracle.sam3d_compare checks us against 60 digits).
TEST(AffinePower3, AgreesWithLongDoublePowOnRandomAffinities) {
  RandomAffinities random(3);
  double worst = 0.0, worst_eigen_double = 0.0;
  for (int i = 0; i < 300; ++i) {
    const Affine3 A = random.next(1e3, 10.0);
    const double t = random.uniform(-1.0, 2.0);
    const Affine3 ours = affine_power(A, t);
    const Eigen::Matrix<long double, 4, 4> H = homogeneous(A).cast<long double>();
    const Eigen::Matrix<long double, 4, 4> P = oracle::pow(H, static_cast<long double>(t));
    const Affine3 reference = affine3_of(Matrix4d(P.cast<double>()));
    const double e = relative_error(ours, reference);
    worst = std::max(worst, e);
    worst_eigen_double = std::max(worst_eigen_double, relative_error(eigen_power(A, t), reference));
    EXPECT_LE(e, 1e-12) << "case " << i << " t " << t << ": " << where(ours, reference);
  }
  std::printf("worst relative difference from the long-double pow: %.2g (Eigen's double pow: %.2g)\n", worst,
              worst_eigen_double);
}

// Near the identity (three eigenvalues within 1e-12 .. 1e-3 of 1), where
// the cubic finds the eigenvalues only to the cube root of rounding: the
// power and the log move by |A - I| or less, and must be right relative to
// that, not only to |A| (docs/paper-notes.md N80).
TEST(AffinePower3, PowersAndLogNearTheIdentityAreRightRelativeToTheMotion) {
  std::mt19937 rng(80);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst_power = 0.0, worst_log = 0.0;
  for (const double epsilon : {1e-12, 1e-10, 1e-8, 1e-6, 1e-5, 3e-5, 1e-4, 1e-3}) {
    for (int i = 0; i < 40; ++i) {
      Affine3 A;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) A.L(r, c) += epsilon * u(rng);
        A.b(r) = epsilon * u(rng);
      }
      const double motion = (homogeneous(A) - Matrix4d::Identity()).norm();
      const Eigen::Matrix<long double, 4, 4> H = homogeneous(A).cast<long double>();
      for (const double t : {0.5, -0.3, 1.7}) {
        const Matrix4d reference = oracle::pow(H, static_cast<long double>(t)).cast<double>();
        // 1e-9 of the motion, and what a split left to 64 ulps of |L|
        // (limits::kSplitResidual) may add: 1e-13 (before N80: up to 0.4 of the motion).
        const double e = (homogeneous(affine_power(A, t)) - reference).norm() / (1e-9 * motion + 1e-13);
        worst_power = std::max(worst_power, e);
        EXPECT_LE(e, 1.0) << "epsilon " << epsilon << " case " << i << " t " << t;
      }
      // log A = O(epsilon), against a long-double log good to ~1e-18 of |A|.
      Matrix4d difference = homogeneous(log(A)) - oracle::log(H).cast<double>();
      difference(3, 3) -= 1.0;
      const double e = difference.norm() / (1e-9 * motion + 1e-17);
      worst_log = std::max(worst_log, e);
      EXPECT_LE(e, 1.0) << "epsilon " << epsilon << " case " << i;
    }
  }
  std::printf("near the identity, worst error in units of 1e-9 |A - I| (and of rounding): power %.2g, log %.2g\n",
              worst_power, worst_log);
}

TEST(AffinePower3, HomogeneousLogAgreesWithEigenLog) {
  RandomAffinities random(4);
  for (int i = 0; i < 100; ++i) {
    const Affine3 A = random.next(1e2, 5.0);
    const Affine3 ours = log(A);
    const Matrix4d theirs = oracle::log(homogeneous(A));
    // (homogeneous(ours) has a 1 in the corner, the log a 0.)
    Matrix4d difference = homogeneous(ours) - theirs;
    difference(3, 3) -= 1.0;
    EXPECT_LE(difference.norm() / std::max(theirs.norm(), 1.0), 1e-11) << "case " << i;
  }
}

TEST(AffinePower3, FixedPointIsFixed) {
  RandomAffinities random(5);
  for (int i = 0; i < 50; ++i) {
    const Affine3 A = random.next(1e2, 5.0);
    const std::optional<Vector3d> q = fixed_point(A);
    if (!q) continue;
    const Vector3d moved = apply(affine_power(A, 0.37), *q);
    EXPECT_LE((moved - *q).norm(), 1e-12 * std::max(1.0, q->norm()));
  }
  Affine3 translation;
  translation.b = Vector3d(1.0, 2.0, 3.0);
  EXPECT_FALSE(fixed_point(translation).has_value());
}

// ------------------------------------------------------------ the cases of A.6

const std::vector<double> kTimes = {-1.5, -0.3, 0.25, 0.5, 0.71, 1.5, 2.25};

TEST(AffinePower3Cases, Identity) {
  for (double t : kTimes) EXPECT_EQ(homogeneous(affine_power(Affine3::identity(), t)), Matrix4d::Identity());
}

TEST(AffinePower3Cases, PureTranslationMovesAtConstantSpeed) {
  Affine3 A;
  A.b = Vector3d(2.5, -0.75, 1.25);
  for (double t : kTimes) EXPECT_AFFINE_NEAR(affine_power(A, t), (Affine3{Matrix3d::Identity(), t * A.b}), 1e-15);
}

// Eigenvalue 1 simple, the others complex: a screw motion. A turns by theta
// about the line through p along u and slides by d along it; A^t turns by
// t theta and slides by t d (A.6: the kernel of L - I carries the
// constant-velocity translation).
TEST(AffinePower3Cases, ScrewMotion) {
  const Vector3d u = Vector3d(1.0, -2.0, 0.5).normalized();
  const Vector3d p(0.3, 1.1, -0.7);
  const double theta = 2.2, d = 1.7;
  const auto screw = [&](double angle, double slide) {
    const Matrix3d R = rotation(u, angle);
    return Affine3{R, p - R * p + slide * u};
  };
  const AffinePowers powers(screw(theta, d));
  for (double t : kTimes) EXPECT_AFFINE_NEAR(powers.at(t), screw(t * theta, t * d), 1e-14) << "t " << t;
  EXPECT_FALSE(fixed_point(screw(theta, d)).has_value());
}

// Eigenvalue 1 simple, the others real: a diagonal in a rotated frame.
TEST(AffinePower3Cases, EigenvalueOneSimpleDiagonal) {
  const Matrix3d R = rotation(Vector3d(0.2, 0.9, -0.4), 0.8);
  const Vector3d values(1.0, 2.0, 0.3), b(0.7, -1.2, 2.0);  // in the rotated frame
  const Affine3 A{R * values.asDiagonal() * R.transpose(), R * b};
  for (double t : kTimes) {
    Vector3d power, translation;
    for (int i = 0; i < 3; ++i) {
      power(i) = std::pow(values(i), t);
      translation(i) = values(i) == 1.0 ? t * b(i) : (power(i) - 1.0) / (values(i) - 1.0) * b(i);
    }
    EXPECT_AFFINE_NEAR(affine_power(A, t), (Affine3{R * power.asDiagonal() * R.transpose(), R * translation}), 1e-14)
        << "t " << t;
  }
}

// Eigenvalue 1 double (a 2D eigenspace) and a scaling; and 1 double as a
// shear beside a scaling.
TEST(AffinePower3Cases, EigenvalueOneDouble) {
  const Vector3d b(0.4, -2.0, 1.5);
  const Affine3 A{Vector3d(1.0, 3.0, 1.0).asDiagonal(), b};
  for (double t : kTimes) {
    const double s = std::pow(3.0, t);
    const Affine3 expected{Vector3d(1.0, s, 1.0).asDiagonal(), Vector3d(t * b(0), (s - 1.0) / 2.0 * b(1), t * b(2))};
    EXPECT_AFFINE_NEAR(affine_power(A, t), expected, 1e-14) << "t " << t;
  }
  // [[1, k, 0], [0, 1, 0], [0, 0, 3]]: the shear's power is [[1, t k], [0, 1]],
  // its translation t b + t (t - 1)/2 (L - I) b; the scaling as above.
  const double k = 1.7;
  Matrix3d L;
  L << 1, k, 0, 0, 1, 0, 0, 0, 3;
  const Affine3 S{L, b};
  for (double t : kTimes) {
    const double s = std::pow(3.0, t);
    Matrix3d Lt;
    Lt << 1, t * k, 0, 0, 1, 0, 0, 0, s;
    const Vector3d bt(t * b(0) + t * (t - 1.0) / 2.0 * k * b(1), t * b(1), (s - 1.0) / 2.0 * b(2));
    EXPECT_AFFINE_NEAR(affine_power(S, t), (Affine3{Lt, bt}), 1e-14) << "t " << t;
  }
}

// Eigenvalue 1 triple: a shear beside 1 (a Jordan block of size 2) and a
// Jordan block of size 3, L = I + N: L^t = I + t N + C(t, 2) N^2 and the
// translation t b + C(t, 2) N b + C(t, 3) N^2 b, in a rotated frame.
TEST(AffinePower3Cases, EigenvalueOneTripleJordanBlocks) {
  const Matrix3d R = rotation(Vector3d(-0.3, 0.5, 0.8), 1.1);
  const Vector3d b(1.0, -0.5, 0.25);
  for (const double c : {0.0, 0.9}) {  // c = 0: N^2 = 0 (a 2x2 block beside 1)
    Matrix3d N;
    N << 0, 1.3, c, 0, 0, (c == 0.0 ? 0.0 : -0.6), 0, 0, 0;
    const Affine3 A{R * (Matrix3d::Identity() + N) * R.transpose(), R * b};
    for (double t : kTimes) {
      const double c2 = t * (t - 1.0) / 2.0, c3 = c2 * (t - 2.0) / 3.0;
      const Matrix3d Lt = Matrix3d::Identity() + t * N + c2 * N * N;
      const Vector3d bt = t * b + c2 * N * b + c3 * N * N * b;
      EXPECT_AFFINE_NEAR(affine_power(A, t), (Affine3{R * Lt * R.transpose(), R * bt}), 1e-14)
          << "c " << c << " t " << t;
    }
  }
}

// Beyond |t| = 16 near the identity the series is reached by squaring (as in
// 2D): a Jordan block of size 3 at 1 keeps its closed form far out.
TEST(AffinePower3Cases, LargeTimesThroughSquaring) {
  Matrix3d N;
  N << 0, 0.4, 0.2, 0, 0, -0.3, 0, 0, 0;
  const Vector3d b(0.5, 1.0, -0.25);
  const AffinePowers powers(Affine3{Matrix3d::Identity() + N, b});
  for (const double t : {-40.0, 37.5, 100.25}) {
    const double c2 = t * (t - 1.0) / 2.0, c3 = c2 * (t - 2.0) / 3.0;
    const Affine3 expected{Matrix3d::Identity() + t * N + c2 * N * N, t * b + c2 * N * b + c3 * N * N * b};
    EXPECT_AFFINE_NEAR(powers.at(t), expected, 1e-14) << "t " << t;
  }
}

// Jordan blocks away from 1: [[2, 1], [0, 2]] beside 5, and 2 (I + N) of size 3;
// the translation through the fixed point (SAM Eq. 9): (I - L^t) q.
TEST(AffinePower3Cases, JordanBlocksAwayFromOne) {
  const Vector3d b(0.5, -1.0, 2.0);
  Matrix3d L2;
  L2 << 2, 1, 0, 0, 2, 0, 0, 0, 5;
  Matrix3d N;
  N << 0, 0.7, -0.4, 0, 0, 1.2, 0, 0, 0;
  const Matrix3d L3 = 2.0 * (Matrix3d::Identity() + N);
  for (double t : kTimes) {
    const double p = std::pow(2.0, t);
    Matrix3d Lt2;
    Lt2 << p, t * p / 2.0, 0, 0, p, 0, 0, 0, std::pow(5.0, t);
    const Vector3d q2 = (Matrix3d::Identity() - L2).inverse() * b;
    EXPECT_AFFINE_NEAR(affine_power(Affine3{L2, b}, t), (Affine3{Lt2, q2 - Lt2 * q2}), 1e-14) << "t " << t;
    const Matrix3d Lt3 = p * (Matrix3d::Identity() + t * N + t * (t - 1.0) / 2.0 * N * N);
    const Vector3d q3 = (Matrix3d::Identity() - L3).inverse() * b;
    EXPECT_AFFINE_NEAR(affine_power(Affine3{L3, b}, t), (Affine3{Lt3, q3 - Lt3 * q3}), 1e-14) << "t " << t;
  }
}

TEST(AffinePower3Cases, DiagonalStretches) {
  const Vector3d values(1e4, 1e-4, 3.0), b(1.0, -1.0, 0.5);
  const Affine3 A{values.asDiagonal(), b};
  for (double t : kTimes) {
    Vector3d power, translation;
    for (int i = 0; i < 3; ++i) {
      power(i) = std::pow(values(i), t);
      translation(i) = (power(i) - 1.0) / (values(i) - 1.0) * b(i);
    }
    // Normwise: the plane's 2D EAR (spectral projectors) gives the small
    // eigenvalue to 1e-16 of the larger one, not to its own relative accuracy.
    EXPECT_AFFINE_NEAR(affine_power(A, t), (Affine3{power.asDiagonal(), translation}), 1e-14) << "t " << t;
  }
}

// A planar affinity beside a scaling equals the 2D EAR on its plane.
TEST(AffinePower3Cases, EmbeddedPlanarAffinitiesEqualTheTwoDimensionalEar) {
  std::vector<Matrix2d> planes(5);
  planes[0] << 1.2, -0.8, 0.6, 0.9;                                                                      // G1
  planes[1] << 2.0, 0.5, 0.3, 0.7;                                                                       // G2
  planes[2] << 1.0, 0.0, 0.0, 2.5;                                                                       // S1
  planes[3] = -1.5 * Matrix2d::Identity();                                                               // S2
  planes[4] << std::cos(kPi - 1e-7), -std::sin(kPi - 1e-7), std::sin(kPi - 1e-7), std::cos(kPi - 1e-7);  // near pi
  const Vector2d c(0.3, -1.4);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    for (const double lambda : {1.0, 0.5, 7.0}) {
      Affine3 A;
      A.L.topLeftCorner<2, 2>() = planes[i];
      A.L(2, 2) = lambda;
      A.b << c, 0.8;
      for (double t : kTimes) {
        const Affine2 planar = affine_power(Affine2{planes[i], c}, t);
        Affine3 expected;
        expected.L.topLeftCorner<2, 2>() = planar.L;
        expected.L(2, 2) = std::pow(lambda, t);
        expected.b << planar.b, (lambda == 1.0 ? t : (std::pow(lambda, t) - 1.0) / (lambda - 1.0)) * 0.8;
        // S2 is the half turn by +pi about e3 (N58: e3's largest component is positive).
        EXPECT_AFFINE_NEAR(affine_power(A, t), expected, 1e-14) << "plane " << i << " lambda " << lambda << " t " << t;
      }
    }
  }
}

// A rotation by pi about an axis (eigenvalues 1, -1, -1) with a slide along
// it: A^t turns by t pi about the axis, the way fixed in N58 (the axis's
// largest component positive, turning counter-clockwise seen from its tip).
TEST(AffinePower3Cases, HalfTurnAboutAnAxis) {
  const Vector3d u = Vector3d(0.3, -0.9, 0.2).normalized();  // largest component negative
  const Vector3d axis = -u;                                  // the canonical direction
  const Vector3d p(1.0, 0.5, -0.25);
  const double d = 0.6, scale = 2.0;
  const auto turn = [&](double angle, double slide, double lambda_t, double rho_t) {
    const Matrix3d P = axis * axis.transpose();
    const Matrix3d L = lambda_t * P + rho_t * rotation(axis, angle) * (Matrix3d::Identity() - P);
    return Affine3{L, p - L * p + slide * axis};
  };
  const Affine3 A = turn(kPi, d, 1.0, 1.0);
  const AffinePowers powers(A);
  for (double t : kTimes) EXPECT_AFFINE_NEAR(powers.at(t), turn(t * kPi, t * d, 1.0, 1.0), 1e-14) << "t " << t;
  const Affine3 half = powers.at(0.5);
  EXPECT_AFFINE_NEAR(compose(half, half), A, 1e-15);
  // With scaling: 3 along the axis, 2 across (the axis is then an eigenvalue 3, the
  // plane -2 I: S2 beside a scaling; no slide, a fixed point p).
  const Affine3 B = turn(kPi, 0.0, 3.0, scale);
  for (double t : kTimes) {
    EXPECT_AFFINE_NEAR(affine_power(B, t), turn(t * kPi, 0.0, std::pow(3.0, t), std::pow(scale, t)), 1e-14)
        << "t " << t;
  }
}

// Near pi the rotation keeps its principal angle, from either side. The log
// of a rotation by pi - e has condition number ~pi/e: the rounding of the
// basis (1e-16) reaches A^t as ~1e-16/e, in Eigen's Schur form as in our
// split, so the tolerance is that (N58).
TEST(AffinePower3Cases, NearHalfTurns) {
  const Vector3d u = Vector3d(0.6, 0.2, -0.77).normalized();
  for (const double angle : {kPi - 1e-6, kPi - 1e-9, -kPi + 1e-9}) {
    const Affine3 A{rotation(u, angle), Vector3d(0.1, 0.2, 0.3)};
    const std::optional<Vector3d> q = fixed_point(A);  // 1 is an eigenvalue: none
    EXPECT_FALSE(q.has_value());
    for (double t : {0.25, 0.5, 0.75}) {
      const double tolerance = std::max(1e-14, 1e-15 / (kPi - std::abs(angle)));
      const Affine3 got = affine_power(A, t);
      EXPECT_LE((got.L - rotation(u, t * angle)).norm(), tolerance) << "angle " << angle << " t " << t;
      const Affine3 theirs = eigen_power(A, t);
      EXPECT_AFFINE_NEAR(got, theirs, 2.0 * tolerance) << "angle " << angle;
    }
  }
}

// ------------------------------------------------------------ no real log

// with_translation(b) is AffinePowers(Affine3{L, b}) bit for bit, in each way
// of computing the corner (series near I, over lambda - 1, over lambda I - M).
TEST(AffinePower3, WithTranslationIsAFreshConstruction) {
  const Vector3d b(-0.7, 2.5, 1.25);
  Matrix3d near_identity = Matrix3d::Identity();
  near_identity(0, 1) = 0.05;
  near_identity(2, 0) = -0.03;
  Matrix3d stretch = Matrix3d::Zero();
  stretch.diagonal() << 3.0, 0.5, 0.6;
  stretch(0, 2) = 0.4;
  Matrix3d lean = Matrix3d::Zero();
  lean.diagonal() << 1.5, 3.0, 3.2;
  lean(0, 1) = 0.3;
  lean(1, 2) = -0.2;
  for (const Matrix3d& L : {near_identity, Matrix3d(2.0 * rotation(Vector3d(1, 2, 2), 0.9)), stretch, lean}) {
    const AffinePowers fresh(Affine3{L, b});
    const AffinePowers moved = AffinePowers(Affine3{L, Vector3d(4.0, -1.0, 0.5)}).with_translation(b);
    EXPECT_EQ(moved.affinity().b, b);
    EXPECT_EQ(moved.log().L, fresh.log().L);
    EXPECT_EQ(moved.log().b, fresh.log().b);
    for (const double t : {-1.3, 0.25, 0.5, 2.0, 7.0}) {
      EXPECT_EQ(moved.at(t).L, fresh.at(t).L) << t;
      EXPECT_EQ(moved.at(t).b, fresh.at(t).b) << t;
      EXPECT_EQ(moved.velocity(t).b, fresh.velocity(t).b) << t;
    }
  }
  EXPECT_THROW((void)AffinePowers(Affine3::identity()).with_translation(Vector3d(0.0, NAN, 0.0)), NoRealLogarithm);
}

// velocity(t) = d/dt A^t = log(A) A^t (central differences).
TEST(AffinePower3, VelocityIsTheDerivative) {
  const AffinePowers powers(Affine3{1.5 * rotation(Vector3d(1, 0, 1).normalized(), 0.6), Vector3d(1.0, -2.0, 0.5)});
  const double h = 1e-6;
  for (const double t : {-0.5, 0.0, 0.4, 1.0, 2.5}) {
    const Affine3 before = powers.at(t - h), after = powers.at(t + h), rate = powers.velocity(t);
    EXPECT_LT((rate.L - (after.L - before.L) / (2.0 * h)).norm(), 1e-7) << t;
    EXPECT_LT((rate.b - (after.b - before.b) / (2.0 * h)).norm(), 1e-7) << t;
  }
}

TEST(AffinePower3, NoRealLogarithmIsRefusedWithTheEigenvalues) {
  struct Case {
    Matrix3d L;
    std::vector<std::string> words;
  };
  std::vector<Case> cases(5);
  cases[0].L = Vector3d(2.0, -0.5, -3.0).asDiagonal();  // two distinct negatives
  cases[0].words = {"-0.5", "-3", "2", "no real logarithm"};
  cases[1].L << -1, 1, 0, 0, -1, 0, 0, 0, 4;  // a negative Jordan block
  cases[1].words = {"-1", "4", "independent eigenvectors"};
  cases[2].L = Vector3d(-1.0, 1.0, 1.0).asDiagonal();  // a mirror
  cases[2].words = {"determinant -1", "orientation"};
  cases[3].L = Vector3d(1.0, 2.0, 0.0).asDiagonal();  // singular
  cases[3].words = {"determinant 0"};
  cases[4].L = rotation(Vector3d(1, 1, 1), 0.4) * Vector3d(5.0, -1.0, -2.0).asDiagonal() *
               rotation(Vector3d(1, 1, 1), -0.4);  // rotated negatives
  cases[4].words = {"-1", "-2", "5"};
  for (const Case& c : cases) {
    try {
      AffinePowers powers(Affine3{c.L, Vector3d(1, 2, 3)});
      ADD_FAILURE() << "no refusal for\n" << c.L;
    } catch (const NoRealLogarithm& error) {
      EXPECT_EQ(error.root_case(), RootCase::G3);
      for (const std::string& word : c.words) {
        EXPECT_NE(std::string(error.what()).find(word), std::string::npos) << error.what() << " lacks " << word;
      }
    }
  }
}

TEST(AffinePower3, EigenvaluesOfTheCubic) {
  const auto values = eigenvalues(Matrix3d(Vector3d(3.0, -1.0, 0.5).asDiagonal()));
  EXPECT_NEAR(values[0].real(), 3.0, 1e-15);
  EXPECT_NEAR(values[1].real(), 0.5, 1e-15);
  EXPECT_NEAR(values[2].real(), -1.0, 1e-15);
  const auto turn = eigenvalues(Matrix3d(2.0 * rotation(Vector3d(0, 0, 1), 0.5)));
  EXPECT_NEAR(turn[0].real(), 2.0, 1e-15);
  EXPECT_NEAR(turn[1].real(), 2.0 * std::cos(0.5), 1e-15);
  EXPECT_NEAR(turn[1].imag(), 2.0 * std::sin(0.5), 1e-15);
}

}  // namespace
}  // namespace pita
