// The Steady Affine Morph of the plane and of space, one template
// (src/core/steady_affine_morph.cpp). The 2D SAM's properties are tested
// beside the 2D EAR (test_affine_power.cpp, suite SteadyAffineMorph).
#include <cmath>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/steady_affine_morph.hpp"

namespace pita {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using Eigen::Vector3d;

double sam3_distance(const Affine3& X, const Affine3& Y) { return (X.L - Y.L).norm() + (X.b - Y.b).norm(); }

const Affine3 kB3{2.0 * Eigen::AngleAxisd(0.4, Vector3d(0, 0, 1)).toRotationMatrix(), Vector3d(1, 2, 3)};
const Affine3 kC3{Eigen::AngleAxisd(1.9, Vector3d(1, 1, 0).normalized()).toRotationMatrix(), Vector3d(-2, 0, 1)};

TEST(SteadyAffineMorph3, EndsAtItsPosesAndIsSteady) {
  const SteadyAffineMorph morph(kB3, kC3);
  EXPECT_EQ(sam3_distance(morph.at(0.0), kB3), 0.0);
  EXPECT_EQ(sam3_distance(morph.at(1.0), kC3), 0.0);
  // Steady: the relative motion from u to u + h is the same for every u.
  const double h = 0.2;
  const Affine3 step0 = compose(morph.at(0.1 + h), inverse(morph.at(0.1)));
  const Affine3 step1 = compose(morph.at(0.7 + h), inverse(morph.at(0.7)));
  EXPECT_LT(sam3_distance(step0, step1), 1e-13);
  // Symmetric: the SAM from C to B runs the same poses backwards.
  const SteadyAffineMorph back(kC3, kB3);
  for (const double u : {0.25, 0.5, 0.8}) EXPECT_LT(sam3_distance(morph.at(u), back.at(1.0 - u)), 1e-13) << u;
}

TEST(SteadyAffineMorph3, VelocityIsTheDerivative) {
  const SteadyAffineMorph morph(kB3, kC3);
  for (const double u : {0.0, 0.3, 0.9}) {
    const double h = 1e-6;
    const Affine3 before = morph.at(u - h), after = morph.at(u + h);
    const Affine3 expected{(after.L - before.L) / (2.0 * h), (after.b - before.b) / (2.0 * h)};
    EXPECT_LT(sam3_distance(morph.velocity(u), expected), 1e-7) << u;
  }
}

// From a pose 1e-50 the size of the other: A = C o B^-1 has a translation of
// 1e50, which the SAM's b_B + g_u(L)(b_C - b_B) never forms. For B = [s R |
// b_B], C = identity: L = R^T / s, and the translation is (I - g_u(L)) b_B,
// g_u(L) = (L^u - I)(L - I)^-1 with L^u = s^-u R(-u theta) about R's axis,
// evaluated here in long double.
TEST(SteadyAffineMorph3, FromATinyPose) {
  using Matrix3L = Eigen::Matrix<long double, 3, 3>;
  using Vector3L = Eigen::Matrix<long double, 3, 1>;
  const Vector3d axis = Vector3d(1, 2, 2).normalized();
  const double theta = 0.7;
  const Vector3d b_B(3.0, 4.0, -1.0);
  for (const double s : {1e-8, 1e-50}) {
    const Affine3 B{s * Eigen::AngleAxisd(theta, axis).toRotationMatrix(), b_B};
    const SteadyAffineMorph sam(B, Affine3::identity());
    for (const double u : {0.5, 1.5}) {
      const Matrix3L L = Eigen::AngleAxis<long double>(-theta, axis.cast<long double>()).toRotationMatrix() / s;
      const Matrix3L Lu = std::pow(static_cast<long double>(s), -static_cast<long double>(u)) *
                          Eigen::AngleAxis<long double>(-u * theta, axis.cast<long double>()).toRotationMatrix();
      const Matrix3L g = (Lu - Matrix3L::Identity()) * (L - Matrix3L::Identity()).inverse();
      const Vector3L expected = (Matrix3L::Identity() - g) * b_B.cast<long double>();
      const Affine3 pose = sam.at(u);
      EXPECT_LT(static_cast<double>((pose.b.cast<long double>() - expected).norm() / expected.norm()), 1e-13)
          << "s = " << s << ", u = " << u;
      EXPECT_LT(static_cast<double>((pose.L.cast<long double>() - Lu * B.L.cast<long double>()).norm() /
                                    (Lu * B.L.cast<long double>()).norm()),
                1e-13)
          << "s = " << s << ", u = " << u;
    }
  }
}

TEST(SteadyAffineMorph3, NoSamBetweenMirroredPosesSaysSo) {
  Affine3 mirrored = kC3;
  mirrored.L.col(2) *= -1.0;
  try {
    const SteadyAffineMorph morph(kB3, mirrored);
    ADD_FAILURE() << "no error";
  } catch (const NoRealLogarithm& error) {
    EXPECT_NE(std::string(error.what()).find("one is mirrored and the other is not"), std::string::npos)
        << error.what();
  }
}

// The template keeps each dimension's floating-point operations: the 2D SAM
// is the power of A with the translation b_C - b_B
// (power_with_translation), its velocity (log L L^u L_B, L^u l(L) (b_C -
// b_B)); the 3D one the power of a second EAR of [L | b_C - b_B], its
// velocity (log L L^u L_B, log L g_u(L) d + l(L) d). Bit for bit.
TEST(SteadyAffineMorph, KeepsTheOperationsOfEachDimension) {
  const Affine2 B{Matrix2d{{1.5, 0.2}, {-0.3, 0.8}}, Vector2d(1.0, -2.0)};
  const Affine2 C{Matrix2d{{0.1, -1.2}, {0.9, 0.4}}, Vector2d(-3.0, 0.5)};
  const SteadyAffineMorph plane(B, C);
  const AffinePowers A(compose(C, inverse(B)));
  const Vector2d d = C.b - B.b;
  const SteadyAffineMorph space(kB3, kC3);
  const AffinePowers change3(Affine3{compose(kC3, inverse(kB3)).L, kC3.b - kB3.b});
  for (const double u : {-0.7, 0.0, 0.25, 0.5, 1.0, 1.75}) {
    const Affine2 power = A.power_with_translation(u, d);
    const Affine2 pose = plane.at(u), rate = plane.velocity(u);
    if (u != 0.0 && u != 1.0) {
      EXPECT_EQ(pose.L, Matrix2d(power.L * B.L)) << u;
      EXPECT_EQ(pose.b, Vector2d(B.b + power.b)) << u;
    }
    EXPECT_EQ(rate.L, Matrix2d(A.linear_log() * power.L * B.L)) << u;
    EXPECT_EQ(rate.b, Vector2d(power.L * A.log_translation(d))) << u;

    const Affine3 power3 = change3.at(u), generator3 = change3.log();
    const Affine3 pose3 = space.at(u), rate3 = space.velocity(u);
    if (u != 0.0 && u != 1.0) {
      EXPECT_EQ(pose3.L, Eigen::Matrix3d(power3.L * kB3.L)) << u;
      EXPECT_EQ(pose3.b, Vector3d(kB3.b + power3.b)) << u;
    }
    EXPECT_EQ(rate3.L, Eigen::Matrix3d(generator3.L * power3.L * kB3.L)) << u;
    EXPECT_EQ(rate3.b, Vector3d(generator3.L * power3.b + generator3.b)) << u;
  }
}

TEST(SteadyAffineMorph, PowersAreThoseOfCAfterBInverse) {
  const SteadyAffineMorph space(kB3, kC3);
  const Affine3 A = compose(kC3, inverse(kB3));
  EXPECT_EQ(space.powers().affinity().L, A.L);
  EXPECT_EQ(space.powers().affinity().b, A.b);
  EXPECT_LT(sam3_distance(compose(space.powers().at(0.4), kB3), space.at(0.4)), 1e-13);
}

TEST(SteadyAffineMorph, FreeFunctionIsTheMorphAtATime) {
  EXPECT_EQ(sam3_distance(steady_affine_morph(kB3, kC3, 0.3), SteadyAffineMorph(kB3, kC3).at(0.3)), 0.0);
  const Affine2 B = Affine2::identity();
  const Affine2 C{Matrix2d{{0.0, -2.0}, {2.0, 0.0}}, Vector2d(1.0, 1.0)};
  const Affine2 expected = SteadyAffineMorph(B, C).at(0.3), got = steady_affine_morph(B, C, 0.3);
  EXPECT_EQ(got.L, expected.L);
  EXPECT_EQ(got.b, expected.b);
}

}  // namespace
}  // namespace pita
