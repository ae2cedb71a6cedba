// The steps of the pose PITAs (src/core/pose_pitas/morph_and_transport.cpp):
// M and T against the oracle's matrix functions, and the refusals' wording
// (docs/paper-notes.md N73, N74).
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/pose_pitas/morph_and_transport.hpp"
#include "pose_pita_support.hpp"

namespace pita {
namespace {

using test::Hom;
using test::hom;
using test::pose_distance;

template <int N>
void expect_steps_match_oracle(unsigned seed) {
  std::mt19937 rng(seed);
  for (int i = 0; i < 20; ++i) {
    const auto k = test::random_triple<N>(rng);
    const Affine<N>&A = k[0].pose, &B = k[1].pose, &X = k[2].pose;
    const SteadyAffineMorph<Affine<N>> morph(A, B);
    for (const double s : {-0.5, 0.0, 0.25, 0.5, 1.0, 1.7}) {
      const Affine<N> m = test::of_hom<N>(test::oracle_morph(hom(A), hom(B), s));
      const Affine<N> t = test::of_hom<N>(test::oracle_transport(hom(X), hom(A), hom(B), s));
      EXPECT_LT(pose_distance(morph.at(s), m), 1e-10) << i << " " << s;
      EXPECT_LT(pose_distance(transported(morph, X, s), t), 1e-10) << i << " " << s;
      EXPECT_LT(pose_distance(steady_affine_transport(X, A, B, s), t), 1e-10) << i << " " << s;
    }
  }
}

TEST(PoseMorphAndTransport, MatchMatrixFunctionsInThePlane) { expect_steps_match_oracle<2>(11); }
TEST(PoseMorphAndTransport, MatchMatrixFunctionsInSpace) { expect_steps_match_oracle<3>(12); }

// T(A, A, B, s) = M(A, B, s), and T(X, A, B, 1) = B o A^-1 o X.
TEST(PoseMorphAndTransport, TransportOfTheStartIsTheMorph) {
  std::mt19937 rng(13);
  const auto k = test::random_triple<3>(rng);
  const SteadyAffineMorph<Affine3> morph(k[0].pose, k[1].pose);
  EXPECT_LT(pose_distance(transported(morph, k[0].pose, 0.3), morph.at(0.3)), 1e-13);
  EXPECT_LT(
      pose_distance(transported(morph, k[2].pose, 1.0), compose(k[1].pose, compose(inverse(k[0].pose), k[2].pose))),
      1e-12);
}

const Affine2 kStepIdentity{};
const Affine2 kStepNegative{Eigen::Matrix2d{{-2.0, 0.0}, {0.0, -0.5}}, Eigen::Vector2d(1.0, 0.0)};  // G3
const Affine2 kStepMirror{Eigen::Matrix2d{{1.0, 0.0}, {0.0, -1.0}}, Eigen::Vector2d(0.0, 0.0)};

TEST(PoseMorphAndTransport, NeighboursWithoutSamNameThePairAndTheAdvice) {
  try {
    neighbours_morph(kStepIdentity, kStepNegative, 1);
    FAIL() << "no throw";
  } catch (const NoPosePitaPower& error) {
    EXPECT_EQ(error.first(), 1u);
    EXPECT_EQ(error.where(), "");
    EXPECT_FALSE(error.time().has_value());
    const std::string what = error.what();
    EXPECT_EQ(what.rfind("no SAM exists between these poses: A = C o B^-1 has no real power (", 0), 0u) << what;
    EXPECT_NE(what.find("move the middle pose so that it turns from each neighbour by less than pi"), std::string::npos)
        << what;
    EXPECT_EQ(error.root_case(), RootCase::G3);
  }
}

TEST(PoseMorphAndTransport, MirroredNeighboursSayMirrorBoth) {
  try {
    neighbours_morph(kStepIdentity, kStepMirror, 0);
    FAIL() << "no throw";
  } catch (const NoSamBetweenPoses& error) {
    EXPECT_EQ(error.first(), 0u);
    EXPECT_NE(std::string(error.what()).find("mirror both poses or neither"), std::string::npos) << error.what();
  }
}

TEST(PoseMorphAndTransport, FormedPosesNameTheStepAndTheTime) {
  try {
    formed_morph(kStepIdentity, kStepNegative, "between L(t) and R(t), which P6 averages", 0.25);
    FAIL() << "no throw";
  } catch (const NoPosePitaPower& error) {
    EXPECT_EQ(error.where(), "between L(t) and R(t), which P6 averages at t = 0.25");
    ASSERT_TRUE(error.time().has_value());
    EXPECT_EQ(*error.time(), 0.25);
    const std::string what = error.what();
    EXPECT_NE(what.find("poses whose neighbours turn by less than pi, or another middle pose, avoid it"),
              std::string::npos)
        << what;
  }
  try {
    formed_morph(kStepIdentity, kStepNegative, "between A and the control pose L of P4");
    FAIL() << "no throw";
  } catch (const NoPosePitaPower& error) {
    EXPECT_EQ(error.where(), "between A and the control pose L of P4");
    EXPECT_FALSE(error.time().has_value());
  }
}

TEST(PoseMorphAndTransport, PoseLogIsTheHomogeneousLogOrARefusal) {
  std::mt19937 rng(14);
  const auto k = test::random_triple<3>(rng, test::Shape{0.7, 1.0, 0.25, false});
  const Affine3 log_of = pose_log(k[1].pose, 1);
  const Hom<3> expected = hom(k[1].pose).log();
  EXPECT_LT((log_of.L - expected.topLeftCorner<3, 3>()).norm() + (log_of.b - expected.topRightCorner<3, 1>()).norm(),
            1e-10);
  try {
    pose_log(kStepNegative, 2);
    FAIL() << "no throw";
  } catch (const NoPosePitaPower& error) {
    EXPECT_EQ(error.first(), 2u);
    EXPECT_EQ(error.where(), "pose 2");  // messages say "(pose 2, method P5)", not a pair
    EXPECT_EQ(std::string(error.what()).rfind("pose 2 has no real logarithm (", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace pita
