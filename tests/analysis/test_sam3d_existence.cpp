// The 3D existence experiment (src/analysis/sam3d_existence.cpp, SAM paper
// Sec. 5.2): the existence test against EAR in 3D and against Eigen's general
// eigensolver, the icosahedron's axes, and the bound the search finds against
// a closed form and a brute-force recount with the independent test.
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "analysis/sam3d_existence.hpp"
#include "core/affine_power_of_space.hpp"
#include "support/sanitizers.hpp"

namespace pita::analysis {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Independent of the code under test: Eigen's general (Hessenberg-QR)
// eigenvalues, and Culver for 3x3 away from the measure-zero cases: a real
// log iff no real eigenvalue is <= 0, or the two negative ones are equal
// (then it takes a rotation by pi: not sampled below).
bool eigen_says_real_log(const Matrix3d& L) {
  const Eigen::Vector3cd values = Eigen::EigenSolver<Matrix3d>(L).eigenvalues();
  for (int i = 0; i < 3; ++i) {
    if (std::abs(values(i).imag()) <= 1e-12 * L.norm() && values(i).real() <= 0.0) return false;
  }
  return true;
}

TEST(Sam3dExistence, HasRealLogarithmOnTheCasesCulverNames) {
  EXPECT_TRUE(has_real_logarithm(Matrix3d::Identity()));
  EXPECT_TRUE(has_real_logarithm(Eigen::AngleAxisd(kPi, Vector3d(1, 2, 3).normalized()).toRotationMatrix()));
  EXPECT_TRUE(has_real_logarithm(Vector3d(-2.0, -2.0, 0.5).asDiagonal()));   // -2 twice, two eigenvectors
  EXPECT_FALSE(has_real_logarithm(Vector3d(-1.0, -2.0, 1.0).asDiagonal()));  // two distinct negatives
  EXPECT_FALSE(has_real_logarithm(Vector3d(-1.0, 2.0, 1.0).asDiagonal()));   // det < 0
  Matrix3d jordan;
  jordan << -1, 1, 0, 0, -1, 0, 0, 0, 1;  // a negative Jordan block
  EXPECT_FALSE(has_real_logarithm(jordan));
  // I - p J (J all ones) has the eigenvalue 1 - 3p.
  EXPECT_TRUE(has_real_logarithm(Matrix3d::Identity() - 0.33 * Matrix3d::Ones()));
  EXPECT_FALSE(has_real_logarithm(Matrix3d::Identity() - 0.34 * Matrix3d::Ones()));
}

// On random matrices the closed-form test agrees with Eigen's eigensolver
// and with whether EAR in 3D finds a log.
TEST(Sam3dExistence, HasRealLogarithmAgreesWithEigenAndWithEar) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  int without = 0;
  for (int i = 0; i < 20000; ++i) {
    Matrix3d L;
    for (int k = 0; k < 9; ++k) {
      const double x = normal(rng);
      L(k / 3, k % 3) = x;
    }
    const bool ours = has_real_logarithm(L);
    EXPECT_EQ(ours, eigen_says_real_log(L)) << L;
    bool ear = true;
    try {
      (void)AffinePowers(Affine3{L, Vector3d::Zero()});
    } catch (const NoRealLogarithm&) {
      ear = false;
    }
    EXPECT_EQ(ours, ear) << L;
    without += ours ? 0 : 1;
  }
  EXPECT_GT(without, 5000);  // both answers are well represented
  EXPECT_LT(without, 15000);
}

// The experiment's own kind of matrix, where the fast paths (Descartes'
// signs, the discriminant) decide most cases: rotations by angles up to pi
// about random axes, every entry moved by -p, 0 or +p on the 0.01 grid.
TEST(Sam3dExistence, HasRealLogarithmAgreesWithEigenOnPerturbedRotations) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(0.0, kPi);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<int> sign(-1, 1), hundredths(0, 60);
  int without = 0;
  for (int i = 0; i < 20000; ++i) {
    const double x = normal(rng), y = normal(rng), z = normal(rng);
    const double a = angle(rng);
    const double p = 0.01 * hundredths(rng);
    Matrix3d L = Eigen::AngleAxisd(a, Vector3d(x, y, z).normalized()).toRotationMatrix();
    for (int k = 0; k < 9; ++k) {
      const int s = sign(rng);
      L(k / 3, k % 3) += p * s;
    }
    const bool ours = has_real_logarithm(L);
    EXPECT_EQ(ours, eigen_says_real_log(L)) << "angle " << a << ", p " << p << "\n" << L;
    without += ours ? 0 : 1;
  }
  EXPECT_GT(without, 1000);  // both answers are well represented (1741 of 20000 without)
  EXPECT_LT(without, 19000);
}

TEST(Sam3dExistence, IcosphereAxesAreUnitAndDistinct) {
  EXPECT_EQ(icosphere_axes(0).size(), 6u);
  EXPECT_EQ(icosphere_axes(1).size(), 21u);
  const std::vector<Vector3d> axes = icosphere_axes(2);
  ASSERT_EQ(axes.size(), 81u);  // 162 vertices, one per antipodal pair
  for (std::size_t i = 0; i < axes.size(); ++i) {
    EXPECT_NEAR(axes[i].norm(), 1.0, 1e-15);
    for (std::size_t j = 0; j < i; ++j) EXPECT_LT(std::abs(axes[i].dot(axes[j])), 1.0 - 1e-6) << i << " " << j;
  }
}

// The identity (angle 0) perturbed by -p everywhere is I - p J, without a SAM
// for p > 1/3: no theta can allow more than 0.33 on the grid of 0.01. For
// theta = pi/4 the search finds exactly that, and a brute-force recount with
// Eigen's eigensolver agrees at 0.33 and 0.34.
TEST(Sam3dExistence, QuarterTurnBoundIsTheOneThirdOfTheIdentity) {
  Sam3dExistenceOptions options;
  options.subdivisions = 0;
  options.angles = 5;
  const SafePerturbation safe = largest_safe_perturbation(kPi / 4.0, options);
  EXPECT_NEAR(safe.largest_p, 0.33, 1e-12);
  ASSERT_TRUE(safe.at_next.has_value());
  EXPECT_NEAR(safe.at_next->p, 0.34, 1e-12);

  const auto brute_force_all = [&](double p) {
    for (const Vector3d& axis : icosphere_axes(options.subdivisions)) {
      for (int j = 0; j < options.angles; ++j) {
        const double angle = -kPi / 4.0 + (kPi / 2.0) * j / (options.angles - 1);
        const Matrix3d R = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
        for (int pattern = 0; pattern < 19683; ++pattern) {
          Matrix3d S;
          int code = pattern;
          for (int k = 0; k < 9; ++k, code /= 3) S(k / 3, k % 3) = static_cast<double>(code % 3) - 1.0;
          if (!eigen_says_real_log(R + p * S)) return false;
        }
      }
    }
    return true;
  };
  EXPECT_FALSE(find_no_sam(kPi / 4.0, 0.33, options).has_value());
  if (test::kUnderSanitizers) return;  // the recount runs Eigen alone: the Release suite checks it
  EXPECT_TRUE(brute_force_all(0.33));
  EXPECT_FALSE(brute_force_all(0.34));
}

TEST(Sam3dExistence, FoundConfigurationHasNoSam) {
  Sam3dExistenceOptions options;
  options.subdivisions = 1;
  options.angles = 9;
  const auto failure = find_no_sam(2.0 * kPi / 3.0, 0.4, options);
  ASSERT_TRUE(failure.has_value());
  const Matrix3d L = Eigen::AngleAxisd(failure->angle, failure->axis).toRotationMatrix() + failure->p * failure->signs;
  EXPECT_FALSE(eigen_says_real_log(L)) << L;
  EXPECT_LE(std::abs(failure->angle), 2.0 * kPi / 3.0 + 1e-12);
}

// The search takes shortcuts (27 matrices at once by bounds on the
// characteristic polynomial's coefficients; one matrix when p = 0); it must
// find exactly what testing each matrix in turn finds: the same first
// configuration without a SAM (axes, then patterns in order: one thread), or
// none. Angles on both sides of 2 pi/3 (where the trace of the rotation turns
// negative and the discriminant decides) and up to pi.
TEST(Sam3dExistence, SearchFindsWhatTestingEachMatrixFinds) {
  Sam3dExistenceOptions options;
  options.subdivisions = 0;
  options.angles = 1;
  options.jobs = 1;
  int failures = 0, passes = 0;
  for (const double theta :
       {0.0, kPi / 3.0, 0.6 * kPi, 2.0 * kPi / 3.0, 0.75 * kPi, 5.0 * kPi / 6.0, 11.0 * kPi / 12.0, kPi}) {
    for (const double p : {0.0, 0.05, 0.12, 0.17, 0.25, 0.29, 0.34, 0.5}) {
      std::optional<std::pair<int, int>> expected;  // axis, pattern
      const std::vector<Vector3d> axes = icosphere_axes(0);
      for (int a = 0; a < static_cast<int>(axes.size()) && !expected; ++a) {
        const Matrix3d R = Eigen::AngleAxisd(theta, axes[static_cast<std::size_t>(a)]).toRotationMatrix();
        // At p = 0 every pattern is R: the one whose signs are all 0 (each digit 1).
        const int first = p == 0.0 ? 9841 : 0, end = p == 0.0 ? 9842 : 19683;
        for (int pattern = first; pattern < end; ++pattern) {
          Matrix3d S;
          int code = pattern;
          for (int k = 0; k < 9; ++k, code /= 3) S(k / 3, k % 3) = static_cast<double>(code % 3) - 1.0;
          if (!has_real_logarithm(R + p * S)) {
            expected = std::make_pair(a, pattern);
            break;
          }
        }
      }
      const std::optional<NoSamConfiguration> found = find_no_sam(theta, p, options);
      ASSERT_EQ(found.has_value(), expected.has_value()) << "theta " << theta << " p " << p;
      if (!found) {
        ++passes;
        continue;
      }
      ++failures;
      EXPECT_TRUE(found->axis.isApprox(axes[static_cast<std::size_t>(expected->first)])) << theta << " " << p;
      Matrix3d S;
      int code = expected->second;
      for (int k = 0; k < 9; ++k, code /= 3) S(k / 3, k % 3) = static_cast<double>(code % 3) - 1.0;
      EXPECT_EQ(found->signs, S) << "theta " << theta << " p " << p;
    }
  }
  // Both outcomes are exercised.
  EXPECT_GT(failures, 10);
  EXPECT_GT(passes, 10);
}

// The figure's curve: non-increasing, 1/3 at angle 0 (I - p J), 0 at pi (a
// rotation by pi perturbed splits its double -1), and at every angle the
// bound of the plain experiment at that theta with the curve's angles.
TEST(Sam3dExistence, CurveIsTheExperimentAtEachAngle) {
  Sam3dExistenceOptions options;
  options.subdivisions = 0;
  const int steps = 4;
  const SafeCurve curve = largest_safe_perturbation_curve(steps, options);
  ASSERT_EQ(curve.thetas.size(), 5u);
  ASSERT_EQ(curve.largest_p.size(), 5u);
  EXPECT_NEAR(curve.largest_p.front(), 0.33, 1e-12);
  EXPECT_EQ(curve.largest_p.back(), 0.0);
  for (int k = 0; k <= steps; ++k) {
    EXPECT_NEAR(curve.thetas[k], kPi * k / steps, 1e-15);
    if (k > 0) {
      EXPECT_LE(curve.largest_p[k], curve.largest_p[k - 1]);
    }
    options.angles = 2 * k + 1;  // j pi / steps, j = -k..k
    EXPECT_NEAR(curve.largest_p[k], largest_safe_perturbation(curve.thetas[k], options).largest_p, 1e-12) << k;
  }
  EXPECT_LT(curve.largest_p[3], curve.largest_p[1]);  // it does fall
}

// Independent of the search: Eigen's eigensolver over the negative angles as
// well (the transposition argument) confirms the bound at pi/2, and that one
// step more fails.
TEST(Sam3dExistence, CurveAgreesWithABruteForceRecount) {
  Sam3dExistenceOptions options;
  options.subdivisions = 0;
  const SafeCurve curve = largest_safe_perturbation_curve(4, options);
  const double p = curve.largest_p[2];  // theta = pi/2
  ASSERT_GT(p, 0.05);
  const auto all_have_a_log = [&](double q) {
    for (const Vector3d& axis : icosphere_axes(0)) {
      for (int j = -2; j <= 2; ++j) {
        const Matrix3d R = Eigen::AngleAxisd(kPi * j / 4.0, axis).toRotationMatrix();
        for (int pattern = 0; pattern < 19683; ++pattern) {
          Matrix3d S;
          int code = pattern;
          for (int k = 0; k < 9; ++k, code /= 3) S(k / 3, k % 3) = static_cast<double>(code % 3) - 1.0;
          if (!eigen_says_real_log(R + q * S)) return false;
        }
      }
    }
    return true;
  };
  if (test::kUnderSanitizers) return;  // the recount runs Eigen alone: the Release suite checks it
  EXPECT_TRUE(all_have_a_log(p));
  EXPECT_FALSE(all_have_a_log(p + 0.01));
}

TEST(Sam3dExistence, PaperBoundsAreTheThreeStated) {
  ASSERT_EQ(paper_existence_bounds().size(), 3u);
  EXPECT_DOUBLE_EQ(paper_existence_bounds()[0].p, 0.29);
  EXPECT_DOUBLE_EQ(paper_existence_bounds()[1].p, 0.33);
  EXPECT_DOUBLE_EQ(paper_existence_bounds()[2].p, 0.50);
}

}  // namespace
}  // namespace pita::analysis
