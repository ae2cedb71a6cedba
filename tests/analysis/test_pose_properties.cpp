// The pose properties one triple at a time (analysis/pose_properties.hpp):
// what must hold does (interpolation, symmetry and affine invariance on both
// sides for P6, steadiness of a polySAM), what must fail does (P5's left
// affine invariance, linear interpolation's steadiness, a Bezier SAM's
// interpolation), knot control sees a moved knot, and the numbers do not
// change when the world is moved by a similarity.
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "analysis/pose_audit_configs.hpp"
#include "analysis/pose_properties.hpp"

namespace pita::analysis {
namespace {

using P = PoseProperty;
using M = PoseMethod;

template <class Pose>
std::vector<PoseTriple<Pose>> tame_triples(int count) {
  std::vector<PoseTriple<Pose>> out;
  for (const PoseAuditConfig<Pose>& c : pose_audit_configs<Pose>(7, 3 * count)) {
    if (c.mix == ConfigMix::tame) out.push_back(c.poses);
  }
  return out;
}

template <class Pose>
double largest(P property, M method, const std::vector<PoseTriple<Pose>>& triples, int* measured = nullptr) {
  double worst = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < triples.size(); ++i) {
    const PoseProbe p = probe_pose(property, method, triples[i], 100 + i);
    if (std::isnan(p.value)) continue;
    worst = std::max(worst, p.value / p.scale);
    ++count;
  }
  if (measured != nullptr) *measured = count;
  return worst;
}

template <class Pose>
void expect_p6_invariant(double tolerance) {
  const auto triples = tame_triples<Pose>(12);
  for (P property : {P::interpolates, P::symmetric, P::left_affine_invariant, P::right_affine_invariant}) {
    int measured = 0;
    EXPECT_LE(largest(property, M::p6, triples, &measured), tolerance) << info(property).id;
    EXPECT_GE(measured, 10) << info(property).id;
  }
}

TEST(PoseProperties, P6IsSymmetricAndAffineInvariantOnBothSidesInThePlane) { expect_p6_invariant<Affine2>(1e-12); }

// In space the same, although P6 forms a SAM between L(t) and R(t), which
// meet at B: near the identity the 3D EAR sums the binomial series where
// its split would be inexact (docs/paper-notes.md N80).
TEST(PoseProperties, P6IsSymmetricAndAffineInvariantOnBothSidesInSpace) { expect_p6_invariant<Affine3>(1e-12); }

TEST(PoseProperties, P5IsNotAffineInvariantButIsSymmetric) {
  const auto triples = tame_triples<Affine2>(12);
  EXPECT_GT(largest(P::left_affine_invariant, M::p5, triples), 1e-2);
  EXPECT_GT(largest(P::right_affine_invariant, M::p5, triples), 1e-2);
  EXPECT_LE(largest(P::symmetric, M::p5, triples), 1e-12);
  const auto space = tame_triples<Affine3>(12);
  EXPECT_GT(largest(P::left_affine_invariant, M::p5, space), 1e-2);
}

TEST(PoseProperties, APolySamIsSteadyAndLinearInterpolationIsNot) {
  for (const auto& triple : tame_triples<Affine2>(6)) {
    const PoseProbe sam = probe_pose(P::steady, M::poly_sam, triple, 1);
    EXPECT_LE(sam.value, 1e-6 * sam.scale);
    const PoseProbe linear = probe_pose(P::steady, M::linear, triple, 1);
    EXPECT_GT(linear.value, 1e-2);
  }
  for (const auto& triple : tame_triples<Affine3>(6)) {
    const PoseProbe sam = probe_pose(P::steady, M::poly_sam, triple, 1);
    EXPECT_LE(sam.value, 1e-6 * sam.scale);
  }
}

TEST(PoseProperties, ThreePosesOnOneSamMakeEveryPitaThatSam) {
  // B is the SAM from A to C at B's knot: P4, P6 and P9 are built of steady
  // morphs between poses of that SAM, and are the SAM itself (ARA 0).
  const auto crafted = crafted_pose_configs<Affine2>();
  const auto on_sam = std::find_if(crafted.begin(), crafted.end(),
                                   [](const auto& c) { return c.name.find("one SAM") != std::string::npos; });
  ASSERT_NE(on_sam, crafted.end());
  for (M method : {M::poly_sam, M::p6, M::p9}) {
    const PoseProbe p = probe_pose(P::steady, method, on_sam->poses, 1);
    EXPECT_LE(p.value, 1e-6 * p.scale) << info(method).id;
  }
}

TEST(PoseProperties, KnotControlSeesTheMovedKnotOfP6NotOfAPolySam) {
  for (const auto& triple : tame_triples<Affine2>(6)) {
    EXPECT_GT(probe_pose(P::knot_controlled, M::p6, triple, 1).value, 1e-4);
    EXPECT_LT(probe_pose(P::knot_controlled, M::poly_sam, triple, 1).value, 1e-9);
  }
}

TEST(PoseProperties, ABezierSamMissesItsMiddlePose) {
  const auto triples = tame_triples<Affine2>(6);
  EXPECT_GT(largest(P::interpolates, M::bezier_sam, triples), 1e-2);
  EXPECT_EQ(largest(P::interpolates, M::p9, triples), 0.0);
}

TEST(PoseProperties, NoSamBetweenNeighboursIsNoMotion) {
  // B turned from A and C by 3 rad and stretched: B o A^-1 has two negative eigenvalues.
  PoseTriple<Affine2> k{};
  k[0] = {0.0, Affine2{}};
  Affine2 B;
  B.L << -2.0, 0.1, 0.0, -0.5;
  k[1] = {0.5, B};
  k[2] = {1.0, Affine2{}};
  k[2].pose.b << 1.0, 0.0;
  for (M method : {M::poly_sam, M::p4, M::p6, M::p9}) {
    const PoseProbe exists = probe_pose(P::exists, method, k, 1);
    EXPECT_EQ(exists.value, 1.0) << info(method).id;
    EXPECT_NE(exists.note.find("no"), std::string::npos) << exists.note;
    EXPECT_TRUE(std::isnan(probe_pose(P::symmetric, method, k, 1).value));
  }
}

template <class Pose>
void expect_similarity_free(double tolerance) {
  for (const auto& triple : tame_triples<Pose>(3)) {
    PoseTriple<Pose> moved = triple;
    Pose S;
    S.L = 7.5 * S.L;
    S.L.template topLeftCorner<2, 2>() = 7.5 * Eigen::Rotation2Dd(1.1).toRotationMatrix();
    S.b.setConstant(-3.0);
    S.b[0] = 11.0;
    for (auto& p : moved) p.pose = compose(S, p.pose);
    for (P property : {P::knot_controlled, P::steady}) {
      const double a = probe_pose(property, M::p6, triple, 3).value, b = probe_pose(property, M::p6, moved, 3).value;
      EXPECT_NEAR(a, b, tolerance * std::max(1.0, a)) << info(property).id;
    }
  }
}

TEST(PoseProperties, NumbersDoNotChangeWithASimilarityOfTheWorldInThePlane) { expect_similarity_free<Affine2>(1e-6); }

// In space as in the plane (the 3D EAR near the identity: docs/paper-notes.md N80).
TEST(PoseProperties, NumbersDoNotChangeWithASimilarityOfTheWorldInSpace) { expect_similarity_free<Affine3>(1e-6); }

}  // namespace
}  // namespace pita::analysis
