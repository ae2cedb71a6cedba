// A pose PITA past three poses (src/core/pose_pitas/blend_chain.cpp): through
// every pose, the pose PITA itself for three poses, C1 at the interior knots,
// the arrow blend chain (core/chains/blend_chain.hpp) on similarity poses,
// and refusals counted from the first of all the poses.
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/chains/blend_chain.hpp"
#include "core/pitas/p06_la_lp.hpp"
#include "core/pose_pitas/blend_chain.hpp"
#include "pose_pita_checks.hpp"

namespace pita {
namespace {

// n timed poses G_j o ... o G_1 o A of random steps (turning by at most
// 1.2 rad, stretching by 0.3), knots 0, 1, 2, ... jittered.
template <int N>
std::vector<TimedPoseOf<Affine<N>>> chain_poses(std::mt19937& rng, std::size_t n) {
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<TimedPoseOf<Affine<N>>> poses;
  Affine<N> pose = test::random_step<N>(rng, 1.0, 0.3);
  for (std::size_t j = 0; j < n; ++j) {
    poses.push_back({static_cast<double>(j) + jitter(rng), pose});
    pose = compose(test::random_step<N>(rng, 1.2, 0.3), pose);
  }
  return poses;
}

template <int N>
double chain_distance(const PoseBlendChain<Affine<N>>& chain, double t, const Affine<N>& pose) {
  return test::pose_distance(chain.at(t), pose);
}

TEST(PoseBlendChain, PassesThroughEveryPoseInThePlaneAndInSpace) {
  std::mt19937 rng(31);
  for (int i = 0; i < 10; ++i) {
    const auto plane = chain_poses<2>(rng, 6);
    const auto space = chain_poses<3>(rng, 5);
    for (PoseMethod method : {PoseMethod::p4, PoseMethod::p5, PoseMethod::p6, PoseMethod::p9}) {
      const PoseBlendChain<Affine2> in_plane(method, plane);
      const PoseBlendChain<Affine3> in_space(method, space);
      for (const auto& key : plane) EXPECT_LT(chain_distance<2>(in_plane, key.t, key.pose), 1e-11) << key.t;
      for (const auto& key : space) EXPECT_LT(chain_distance<3>(in_space, key.t, key.pose), 1e-11) << key.t;
    }
  }
}

TEST(PoseBlendChain, OfThreePosesIsThePosePita) {
  std::mt19937 rng(32);
  const auto poses = chain_poses<3>(rng, 3);
  const PoseBlendChain<Affine3> chain(PoseMethod::p6, poses);
  const PoseLaLp<Affine3> pita({poses[0], poses[1], poses[2]});
  for (double t = -0.5; t <= 2.5; t += 0.125) EXPECT_EQ(test::pose_distance(chain.at(t), pita.at(t)), 0.0) << t;
}

// The one-sided derivatives at each interior knot agree (to the error of the
// difference quotients), and they differ visibly at a polySAM's knots.
TEST(PoseBlendChain, IsC1AtInteriorKnots) {
  std::mt19937 rng(33);
  const auto poses = chain_poses<2>(rng, 5);
  const PoseBlendChain<Affine2> chain(PoseMethod::p6, poses);
  const double h = 1e-5;
  for (std::size_t i = 1; i + 1 < poses.size(); ++i) {
    const double t = poses[i].t;
    const Affine2 at = chain.at(t), before = chain.at(t - h), after = chain.at(t + h);
    const Affine2 left{(at.L - before.L) / h, (at.b - before.b) / h};
    const Affine2 right{(after.L - at.L) / h, (after.b - at.b) / h};
    EXPECT_LT(test::pose_distance(left, right), 1e-3) << "knot " << i;
    // A single triple's second derivative is finite: the jump we look for is
    // not hidden by h (a C0 corner would give a difference of order 1).
    EXPECT_GT(test::pose_distance(left, Affine2{}), 1e-2) << "knot " << i;
  }
}

// On similarity poses whose neighbours turn by less than pi, the pose blend
// chain of P6 is the arrow blend chain of P6 on the matching arrows.
TEST(PoseBlendChain, IsTheArrowBlendChainOnSimilarities) {
  std::mt19937 rng(34);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 10; ++i) {
    std::vector<Keyframe> keyframes;
    double w = 3.0 * u(rng);
    for (int j = 0; j < 6; ++j) {
      keyframes.push_back({j + 0.3 * u(rng), Arrow{{3.0 * u(rng), 3.0 * u(rng)}, std::exp(0.7 * u(rng)), w}});
      w += 1.2 * u(rng);
    }
    const BlendChain arrows(keyframes, [](std::span<const Keyframe> k) -> std::unique_ptr<Motion> {
      return std::make_unique<LaLp>(KeyframeTriple{k[0], k[1], k[2]});
    });
    std::vector<TimedPoseOf<Affine2>> plane;
    std::vector<TimedPoseOf<Affine3>> space;
    for (const Keyframe& key : keyframes) {
      plane.push_back({key.t, affine_of(key.arrow)});
      space.push_back({key.t, test::affine3_of(key.arrow)});
    }
    const PoseBlendChain<Affine2> in_plane(PoseMethod::p6, plane);
    const PoseBlendChain<Affine3> in_space(PoseMethod::p6, space);
    for (double t = -0.5; t <= 5.5; t += 0.1) {
      const Arrow expected = arrows.at(t);
      EXPECT_LT(test::pose_distance(in_plane.at(t), affine_of(expected)), 1e-9) << "chain " << i << " t " << t;
      EXPECT_LT(test::pose_distance(in_space.at(t), test::affine3_of(expected)), 1e-9) << "chain " << i << " t " << t;
    }
  }
}

TEST(PoseBlendChain, NamesTheRefusedPairAmongAllThePoses) {
  std::mt19937 rng(35);
  auto poses = chain_poses<2>(rng, 5);
  // Poses 3 and 4 have no SAM: the step between them has the eigenvalue -1 twice.
  Affine2 flip;
  flip.L << -1.0, 0.2, 0.0, -1.0;
  poses[4].pose = compose(flip, poses[3].pose);
  try {
    const PoseBlendChain<Affine2> chain(PoseMethod::p6, poses);
    FAIL() << "no throw";
  } catch (const NoPosePitaPower& error) {
    EXPECT_EQ(error.first(), 3u);
    EXPECT_EQ(error.where(), "");
    EXPECT_FALSE(error.time().has_value());
  }
  EXPECT_THROW(PoseBlendChain<Affine2>(PoseMethod::p6, std::span(poses).first(2)), std::invalid_argument);
}

}  // namespace
}  // namespace pita
