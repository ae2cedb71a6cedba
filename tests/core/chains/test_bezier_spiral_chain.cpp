// The "bezier-spiral" chain (core/chains/bezier_spiral_chain.hpp): cubic
// Beziers of p and q whose inner controls are the span's SMA at 1/3 and 2/3.
#include <numbers>

#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "core/chains/bezier_spiral_chain.hpp"
#include "core/pitas/registry.hpp"
#include "core/steady_morph.hpp"
#include "track_support.hpp"

namespace pita {
namespace {

using test::TrackSampler;

// The cubic in Bernstein form, written out independently of de Casteljau.
Point bernstein(const std::array<Point, 4>& c, double s) {
  const double r = 1.0 - s;
  return r * r * r * c[0] + 3.0 * r * r * s * c[1] + 3.0 * r * s * s * c[2] + s * s * s * c[3];
}

TEST(DeCasteljau, IsTheBernsteinCubicInsideAndOutside) {
  const std::array<Point, 4> c{Point{0, 0}, Point{1, 2}, Point{3, -1}, Point{4, 1}};
  for (double s = -1.0; s <= 2.0; s += 0.125) {
    EXPECT_LT(std::abs(de_casteljau(c, s) - bernstein(c, s)), 1e-12) << s;
  }
}

TEST(BezierSpiralChain, FollowsTheCubicsOfTheSpansSmaSamples) {
  TrackSampler s(9300);
  for (int trial = 0; trial < 8; ++trial) {
    const std::vector<Keyframe> k = s.track(s.integer(2, 8), 12.0, 1.5);
    const auto chain = make_motion(Method::SMA, k, {}, Chain::bezier_spiral);
    const double size = test::extent(k);
    for (std::size_t i = 0; i + 1 < k.size(); ++i) {
      const Arrow third = steady_morph(k[i].arrow, k[i + 1].arrow, 1.0 / 3.0);
      const Arrow two_thirds = steady_morph(k[i].arrow, k[i + 1].arrow, 2.0 / 3.0);
      const std::array<Point, 4> p{k[i].arrow.p, third.p, two_thirds.p, k[i + 1].arrow.p};
      const std::array<Point, 4> q{k[i].arrow.q(), third.q(), two_thirds.q(), k[i + 1].arrow.q()};
      for (double u = 0.0; u < 1.0; u += 0.125) {
        const double t = k[i].t + u * (k[i + 1].t - k[i].t);
        const Arrow frame = chain->at(t);
        EXPECT_LT(std::abs(frame.p - bernstein(p, u)), 1e-9 * size) << "span " << i << " u " << u;
        EXPECT_LT(std::abs(frame.q() - bernstein(q, u)), 1e-9 * size) << "span " << i << " u " << u;
        // Its winding is on the branch of the SMA's (docs/reference/scene-format.md "Keyframe tracks").
        EXPECT_LE(std::abs(frame.w - steady_morph(k[i].arrow, k[i + 1].arrow, u).w), std::numbers::pi + 1e-9);
      }
    }
    // Through every keyframe, windings (several turns) included.
    for (const Keyframe& key : k) {
      EXPECT_TRUE(test::arrows_near(chain->at(key.t), key.arrow, 1e-9, size, false));
    }
  }
}

TEST(BezierSpiralChain, IsSimilarityInvariant) {
  TrackSampler s(9400);
  const std::vector<Keyframe> keys = s.track(5, 6.0);
  const Twirl S = twirl(Point{-1.0, 2.0}, 0.4, -2.5);
  const auto original = make_motion(Method::SMA, keys, {}, Chain::bezier_spiral);
  const auto image = make_motion(Method::SMA, test::moved(S, keys), {}, Chain::bezier_spiral);
  for (double u = -0.2; u <= 1.2; u += 0.05) {
    const double t = keys.front().t + u * (keys.back().t - keys.front().t);
    EXPECT_TRUE(test::arrows_near(image->at(t), S * original->at(t), 1e-8, test::extent(test::moved(S, keys)), false));
  }
}

}  // namespace
}  // namespace pita
