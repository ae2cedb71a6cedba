// Persistent Affine Motion (core/pam.hpp, Sec. 3.3, PITA Eq. 37-39): it
// interpolates its three affinities, agrees with P8 on similarities (two
// independent implementations, one in complex numbers, one in 2x2 matrices),
// is affine-invariant (PITA Eq. 43, the property P8 owes to PAM in Fig. 10), and its
// acceleration is constant in the moving frame (PITA Eq. 39), by finite differences.
#include <optional>

#include <gtest/gtest.h>

#include "core/pam.hpp"
#include "core/pitas/motion.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

Eigen::Matrix3d homogeneous(const Affine2& A) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Identity();
  H.topLeftCorner<2, 2>() = A.L;
  H.topRightCorner<2, 1>() = A.b;
  return H;
}

double distance(const Affine2& X, const Affine2& Y) { return (homogeneous(X) - homogeneous(Y)).cwiseAbs().maxCoeff(); }

Affine2 random_affinity(Sampler& s) {
  Affine2 A;
  // Close to a rotation-scaling so that K stays away from acosh's cut.
  const double angle = s.uniform(-1.0, 1.0), scale = std::exp(s.uniform(-0.5, 0.5));
  A.L << scale * std::cos(angle), -scale * std::sin(angle), scale * std::sin(angle), scale * std::cos(angle);
  A.L += Eigen::Matrix2d::NullaryExpr([&](Eigen::Index, Eigen::Index) { return s.uniform(-0.3, 0.3); });
  A.b << s.uniform(-3.0, 3.0), s.uniform(-3.0, 3.0);
  return A;
}

TEST(Pam, InterpolatesItsAffinities) {
  Sampler s(11);
  for (int i = 0; i < 200; ++i) {
    const Affine2 A = random_affinity(s), B = random_affinity(s), C = random_affinity(s);
    const double b = s.uniform(0.2, 0.8);
    const PersistentAffineMotion U(0.0, A, b, B, 1.0, C);
    EXPECT_LT(distance(U.at(0.0), A), 1e-10) << i;
    EXPECT_LT(distance(U.at(b), B), 1e-10) << i;
    EXPECT_LT(distance(U.at(1.0), C), 1e-10) << i;
  }
}

TEST(Pam, EqualsP8OnSimilarities) {
  Sampler s(12);
  int compared = 0;
  for (int i = 0; i < 200; ++i) {
    const KeyframeTriple k = s.triple(Config::uneven);
    std::unique_ptr<Motion> p8;
    try {
      p8 = motion(Method::P8, k);
    } catch (const MotionDomainError&) {
      continue;  // near kappa = -1: both refuse
    }
    std::optional<PersistentAffineMotion> U;
    try {
      U.emplace(k.a.t, affine_of(k.a.arrow), k.b.t, affine_of(k.b.arrow), k.c.t, affine_of(k.c.arrow));
    } catch (const MotionDomainError&) {
      continue;  // on P8's branch cut, which P8 resolves and PAM refuses
    }
    for (double t : sample_times(k)) {
      EXPECT_LT(distance(U->at(t), affine_of(p8->at(t))), 1e-9 * (1.0 + extent(k))) << i << " t=" << t;
    }
    ++compared;
  }
  EXPECT_GT(compared, 150);
}

TEST(Pam, IsAffineInvariant) {
  Sampler s(13);
  for (int i = 0; i < 100; ++i) {
    const Affine2 A = random_affinity(s), B = random_affinity(s), C = random_affinity(s);
    Affine2 V;
    V.L << s.uniform(0.5, 2.0), s.uniform(-1.0, 1.0), s.uniform(-1.0, 1.0), s.uniform(0.5, 2.0);
    V.b << s.uniform(-5.0, 5.0), s.uniform(-5.0, 5.0);
    const PersistentAffineMotion U(0.0, A, 0.4, B, 1.0, C);
    const PersistentAffineMotion VU(0.0, compose(V, A), 0.4, compose(V, B), 1.0, compose(V, C));
    for (double t = -0.2; t <= 1.2; t += 0.1) {
      EXPECT_LT(distance(VU.at(t), compose(V, U.at(t))), 1e-9) << i << " t=" << t;
    }
  }
}

TEST(Pam, AccelerationIsConstantInTheMovingFrame) {
  // PITA Eq. 39: U'' = U E with E constant; even knots so that tau = 2t - 1 and
  // d/dt = 2 d/dtau, hence U''(t) = 4 U(tau) E.
  Sampler s(14);
  for (int i = 0; i < 50; ++i) {
    const PersistentAffineMotion U(0.0, random_affinity(s), 0.5, random_affinity(s), 1.0, random_affinity(s));
    const Eigen::Matrix3d E = U.local_acceleration();
    const double h = 1e-3;
    for (double t : {0.1, 0.35, 0.6, 0.9}) {
      const Eigen::Matrix3d second =
          (homogeneous(U.at(t + h)) - 2.0 * homogeneous(U.at(t)) + homogeneous(U.at(t - h))) / (h * h);
      const Eigen::Matrix3d expected = 4.0 * homogeneous(U.at(t)) * E;
      EXPECT_LT((second - expected).cwiseAbs().maxCoeff(), 1e-4 * (1.0 + expected.norm())) << i;
    }
  }
}

TEST(Pam, RefusesASingularMiddleAffinity) {
  Affine2 B;
  B.L << 1.0, 2.0, 2.0, 4.0;
  EXPECT_THROW(PersistentAffineMotion(0.0, Affine2::identity(), 0.5, B, 1.0, Affine2::identity()), MotionDomainError);
}

}  // namespace
}  // namespace pita::test
