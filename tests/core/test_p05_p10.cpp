// P5 and P10 against generic matrix log/exp (Eigen's MatrixFunctions) as an
// independent oracle, and the invariance violations docs/paper-notes.md N6-N7
// document, measured.
#include <Eigen/Dense>

#include "core/lagrange_weights.hpp"
#include "support/matrix_functions.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

Eigen::Matrix3d homogeneous(const Arrow& A, Point origin) {  // PITA Eq. A.1, about `origin`
  Eigen::Matrix3d H;
  const Vector v = A.vector();
  H << v.real(), -v.imag(), A.p.real() - origin.real(),  //
      v.imag(), v.real(), A.p.imag() - origin.imag(),    //
      0, 0, 1;
  return H;
}

Arrow arrow_of(const Eigen::Matrix3d& H, Point origin) {
  return {Point{H(0, 2), H(1, 2)} + origin, std::hypot(H(0, 0), H(1, 0)), std::atan2(H(1, 0), H(0, 0))};
}

TEST(HeLp, MatchesGenericMatrixLogAndExp) {
  Sampler s(600);
  for (int i = 0; i < 200; ++i) {
    const KeyframeTriple k = s.triple(Config::uneven);
    const Point o = (k.a.arrow.p + k.b.arrow.p + k.c.arrow.p) / 3.0;  // appendix C
    const Eigen::Matrix3d LA = oracle::log(homogeneous(k.a.arrow, o)), LB = oracle::log(homogeneous(k.b.arrow, o)),
                          LC = oracle::log(homogeneous(k.c.arrow, o));
    const auto P5 = motion(Method::P5, k);
    for (double t : sample_times(k)) {
      const LagrangeWeights l = lagrange_weights(k.a.t, k.b.t, k.c.t, t);
      const Eigen::Matrix3d H = oracle::exp(Eigen::Matrix3d(l.x * LA + l.y * LB + l.z * LC));  // PITA Eq. 33
      EXPECT_TRUE(arrows_near(P5->at(t), arrow_of(H, o), 1e-9, extent(k), true)) << i << " t=" << t;
    }
  }
}

// He-G: H(t) of appendix C about the global origin, with no centroid shift
// (Fig. C.31), against the same oracle about g = 0.
TEST(HeG, MatchesGenericMatrixLogAndExpAboutTheGlobalOrigin) {
  Sampler s(601);
  for (int i = 0; i < 200; ++i) {
    const KeyframeTriple k = s.triple(Config::uneven);
    const Point g{};
    const Eigen::Matrix3d LA = oracle::log(homogeneous(k.a.arrow, g)), LB = oracle::log(homogeneous(k.b.arrow, g)),
                          LC = oracle::log(homogeneous(k.c.arrow, g));
    const auto H = motion(Method::HeG, k);
    for (double t : sample_times(k)) {
      const LagrangeWeights l = lagrange_weights(k.a.t, k.b.t, k.c.t, t);
      const Eigen::Matrix3d M = oracle::exp(Eigen::Matrix3d(l.x * LA + l.y * LB + l.z * LC));  // PITA Eq. 33, about g
      EXPECT_TRUE(arrows_near(H->at(t), arrow_of(M, g), 1e-9, extent(k), true)) << i << " t=" << t;
    }
  }
}

// Appendix C: translating the keyframes moves P5's pattern rigidly with them,
// but changes H(t)'s. (That the two agree when the centroid is the global
// origin follows from the two oracle tests above: both are PITA Eq. 33, about o
// and about g.)
TEST(HeG, TranslationChangesHButNotP5) {
  Sampler s(602);
  double smallest_change = 1e300;
  for (int i = 0; i < 50; ++i) {
    const KeyframeTriple k = s.triple(Config::tame);
    const Twirl shift = translation({s.uniform(2.0, 6.0), s.uniform(-3.0, 3.0)});
    const KeyframeTriple moved = transformed(shift, k);
    const auto p5 = motion(Method::P5, k), p5_moved = motion(Method::P5, moved);
    const auto h = motion(Method::HeG, k), h_moved = motion(Method::HeG, moved);
    double p5_change = 0.0, h_change = 0.0;
    for (double t : sample_times(k)) {
      p5_change = std::max(p5_change, frame_distance(p5_moved->at(t), shift * p5->at(t)) / extent(k));
      h_change = std::max(h_change, frame_distance(h_moved->at(t), shift * h->at(t)) / extent(k));
    }
    EXPECT_LE(p5_change, 1e-12) << i;
    smallest_change = std::min(smallest_change, h_change);
  }
  EXPECT_GT(smallest_change, 1e-3);
}

TEST(PaEl, MatchesGenericMatrixLogAndExp) {
  Sampler s(610);
  for (int i = 0; i < 200; ++i) {
    const KeyframeTriple k = s.triple(Config::wild);
    const auto linear = [](const Arrow& A) {  // PITA Eq. A.2
      Eigen::Matrix2d L;
      const Vector v = A.vector();
      L << v.real(), -v.imag(), v.imag(), v.real();
      return oracle::log(L);
    };
    const auto P10 = motion(Method::P10, k);
    for (double t : sample_times(k)) {
      const LagrangeWeights l = lagrange_weights(k.a.t, k.b.t, k.c.t, t);
      const Eigen::Matrix2d E =
          oracle::exp(Eigen::Matrix2d(l.x * linear(k.a.arrow) + l.y * linear(k.b.arrow) + l.z * linear(k.c.arrow)));
      const Arrow d = P10->at(t);
      EXPECT_NEAR(std::abs(d.vector() - Complex{E(0, 0), E(1, 0)}), 0.0, 1e-9 * d.m) << i << " t=" << t;
      // The blended angle is the weighted sum of principal angles, unreduced.
      const double w =
          lagrange(l, principal_angle(k.a.arrow.w), principal_angle(k.b.arrow.w), principal_angle(k.c.arrow.w));
      EXPECT_NEAR(d.w, w, 1e-12 * (1 + std::abs(w)));
    }
  }
}

// The largest frame deviation from PITA Eq. 40 for similarity S, relative to the
// figure's extent.
double invariance_violation(Method m, const KeyframeTriple& k, const Twirl& S) {
  const auto D = motion(m, k);
  const auto DS = motion(m, transformed(S, k));
  double d = 0.0;
  for (double t : sample_times(k, 21, 0.0)) d = std::max(d, frame_distance(DS->at(t), S * D->at(t)));
  return d / extent(transformed(S, k));
}

TEST(HeLp, RotationAndDilationViolateSimilarityInvarianceMeasurably) {
  // docs/paper-notes.md N7 reports ~4e-3 for a rotation by 0.1 rad and ~3e-2 for
  // a dilation by 2, relative to the figure. We measure the same kind of
  // numbers on a fixed configuration (and record them in the test output).
  const KeyframeTriple k{{0.0, {{0, 0}, 1.0, 0.4}}, {0.5, {{3, 1.5}, 0.6, 2.0}}, {1.0, {{6, 0}, 1.2, 2.8}}};
  const Point o = (k.a.arrow.p + k.b.arrow.p + k.c.arrow.p) / 3.0;
  const double rotation = invariance_violation(Method::P5, k, twirl(o, 1.0, 0.1));
  const double dilation = invariance_violation(Method::P5, k, twirl(o, 2.0, 0.0));
  ::testing::Test::RecordProperty("p5_rotation_0.1rad_violation", std::to_string(rotation));
  ::testing::Test::RecordProperty("p5_dilation_2_violation", std::to_string(dilation));
  std::printf("P5 invariance violation: rotation 0.1 rad %.3g, dilation x2 %.3g (relative to the figure)\n", rotation,
              dilation);
  EXPECT_GT(rotation, 1e-4);
  EXPECT_GT(dilation, 1e-3);
  // The similarity-invariant variant has none.
  EXPECT_LT(invariance_violation(Method::P5S, k, twirl(o, 1.0, 0.1)), 1e-12);
  EXPECT_LT(invariance_violation(Method::P5S, k, twirl(o, 2.0, 0.0)), 1e-12);
  EXPECT_LT(invariance_violation(Method::P5S, k, twirl({3, -2}, 0.7, 2.9)), 1e-12);
}

// H(t) of PITA Eq. 33 about `center` through k's keyframes, by Eigen's generic
// matrix log and exp (the oracle of the tests above).
Arrow blended_oracle(const KeyframeTriple& k, double t, Point center) {
  const LagrangeWeights l = lagrange_weights(k.a.t, k.b.t, k.c.t, t);
  const Eigen::Matrix3d H = oracle::exp(Eigen::Matrix3d(l.x * oracle::log(homogeneous(k.a.arrow, center)) +
                                                        l.y * oracle::log(homogeneous(k.b.arrow, center)) +
                                                        l.z * oracle::log(homogeneous(k.c.arrow, center))));
  return arrow_of(H, center);
}

// max over 201 times of [a, c] of |D_{S k}(t) - S D_k(t)| (frames, world
// units), for H about the global origin (He-G) or about the centroid (P5),
// computed with the oracle alone.
double oracle_violation(const KeyframeTriple& k, const Twirl& S, bool about_centroid) {
  const KeyframeTriple moved = transformed(S, k);
  const auto centroid = [](const KeyframeTriple& x) { return (x.a.arrow.p + x.b.arrow.p + x.c.arrow.p) / 3.0; };
  double d = 0.0;
  for (int i = 0; i <= 200; ++i) {
    const double t = k.a.t + (k.c.t - k.a.t) * i / 200.0;
    const Arrow original = blended_oracle(k, t, about_centroid ? centroid(k) : Point{});
    const Arrow after = blended_oracle(moved, t, about_centroid ? centroid(moved) : Point{});
    d = std::max(d, frame_distance(after, S * original));
  }
  return d;
}

// Appendix C says H(t) is not affected by rotations or dilations about the
// global origin g. With H(S.A) = S H(A), the log of S H(A) is not log S +
// log H(A) unless the translation is zero, so it is: docs/paper-notes.md N56,
// whose numbers (Fig. C.31's keyframes, world units) are checked here against
// the oracle, and the methods against the oracle's numbers.
TEST(HeG, RotationsAndDilationsAboutTheGlobalOriginChangeIt) {
  const KeyframeTriple k{{0.0, {{1, 0.5}, 1.0, -0.4}}, {0.5, {{2.5, 2.5}, 0.7, 1.6}}, {1.0, {{4.5, 1}, 1.2, 2.9}}};
  const Twirl rotation = twirl({0, 0}, 1.0, -0.3), dilation = twirl({0, 0}, 1.7, 0.0);
  const double he_g_rotation = oracle_violation(k, rotation, false),
               he_g_dilation = oracle_violation(k, dilation, false);
  const double p5_rotation = oracle_violation(k, rotation, true), p5_dilation = oracle_violation(k, dilation, true);
  EXPECT_NEAR(he_g_rotation, 0.079, 0.0005);  // N56's printed values, to their digits
  EXPECT_NEAR(he_g_dilation, 0.26, 0.005);
  EXPECT_NEAR(p5_rotation, 0.061, 0.0005);
  EXPECT_NEAR(p5_dilation, 0.19, 0.005);
  // The methods give the oracle's numbers.
  const auto method_violation = [&k](Method m, const Twirl& S) {
    const auto D = motion(m, k), DS = motion(m, transformed(S, k));
    double d = 0.0;
    for (int i = 0; i <= 200; ++i) d = std::max(d, frame_distance(DS->at(i / 200.0), S * D->at(i / 200.0)));
    return d;
  };
  EXPECT_NEAR(method_violation(Method::HeG, rotation), he_g_rotation, 1e-9);
  EXPECT_NEAR(method_violation(Method::HeG, dilation), he_g_dilation, 1e-9);
  EXPECT_NEAR(method_violation(Method::P5, rotation), p5_rotation, 1e-9);
  EXPECT_NEAR(method_violation(Method::P5, dilation), p5_dilation, 1e-9);
  // Keyframes at the origin (zero translations): then the logs commute with S.
  const KeyframeTriple at_g{{0.0, {{0, 0}, 1.0, -0.4}}, {0.5, {{0, 0}, 0.7, 1.6}}, {1.0, {{0, 0}, 1.2, 2.6}}};
  EXPECT_LT(oracle_violation(at_g, twirl({0, 0}, 1.7, -0.3), false), 1e-12);
  EXPECT_LT(invariance_violation(Method::HeG, at_g, twirl({0, 0}, 1.7, -0.3)), 1e-12);
}

TEST(PaEl, RotationAcrossPiViolatesSimilarityInvariance) {
  // B's angle 3.1 rotated by 0.1 crosses pi: its principal angle jumps by -2 pi.
  const KeyframeTriple k{{0.0, {{0, 0}, 1.0, 0.4}}, {0.5, {{3, 1.5}, 0.6, 3.1}}, {1.0, {{6, 0}, 1.2, 2.0}}};
  const double across = invariance_violation(Method::P10, k, twirl({1, 1}, 1.0, 0.1));
  const double within = invariance_violation(Method::P10, k, twirl({1, 1}, 1.0, 0.02));
  EXPECT_GT(across, 1e-2);
  EXPECT_LT(within, 1e-12);
}

}  // namespace
}  // namespace pita::test
