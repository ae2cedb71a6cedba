// The "spiral" chain (core/chains/spiral_chain.hpp): the SMA of PITA Eq. 20-21
// between consecutive keyframes, C0, windings kept, extrapolated past the ends.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "core/chains/spiral_chain.hpp"
#include "core/pitas/registry.hpp"
#include "core/steady_morph.hpp"
#include "track_support.hpp"

namespace pita {
namespace {

using test::TrackSampler;

TEST(SpiralChain, EachSpanIsTheSteadyMorphOfItsKeyframes) {
  TrackSampler s(9000);
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<Keyframe> k = s.track(s.integer(2, 9), 12.0, 2.0);
    const auto chain = make_motion(Method::SMA, k);  // the SMA's default chain
    const double size = test::extent(k);
    for (std::size_t i = 0; i + 1 < k.size(); ++i) {
      for (double u = 0.0; u <= 1.0; u += 0.125) {
        const double t = k[i].t + u * (k[i + 1].t - k[i].t);
        // The last knot of a span is the first of the next: compare there
        // with the keyframe, which both reach.
        const Arrow expected = u == 1.0 ? k[i + 1].arrow : steady_morph(k[i].arrow, k[i + 1].arrow, u);
        EXPECT_TRUE(test::arrows_near(chain->at(t), expected, 1e-9, size, false)) << "span " << i << " u " << u;
      }
    }
    // Past the ends: the first and last SMA, extrapolated along their spirals.
    const std::size_t n = k.size();
    EXPECT_TRUE(test::arrows_near(chain->at(k[0].t - 0.5 * (k[1].t - k[0].t)),
                                  steady_morph(k[0].arrow, k[1].arrow, -0.5), 1e-9, size, false));
    EXPECT_TRUE(test::arrows_near(chain->at(k[n - 1].t + 0.5 * (k[n - 1].t - k[n - 2].t)),
                                  steady_morph(k[n - 2].arrow, k[n - 1].arrow, 1.5), 1e-9, size, false));
  }
}

TEST(SpiralChain, IsTheSameWhateverTheMethodAndContinuousAtKnots) {
  TrackSampler s(9100);
  const std::vector<Keyframe> k = s.track(7, 9.0);
  const auto with_sma = make_motion(Method::SMA, k, {}, Chain::spiral);
  const auto with_p6 = make_motion(Method::P6, k, {}, Chain::spiral);
  for (std::size_t i = 1; i + 1 < k.size(); ++i) {
    const double t = k[i].t, gap = k[i + 1].t - k[i].t;
    EXPECT_TRUE(test::arrows_near(with_p6->at(t), with_sma->at(t), 0.0, 1.0, false));
    EXPECT_TRUE(test::arrows_near(with_sma->at(t - 1e-10 * gap), k[i].arrow, 1e-7, test::extent(k), false));
    EXPECT_TRUE(test::arrows_near(with_sma->at(t + 1e-10 * gap), k[i].arrow, 1e-7, test::extent(k), false));
  }
}

TEST(SpiralChain, OnTwoKeyframesIsTheSma) {
  TrackSampler s(9200);
  const std::vector<Keyframe> k = s.track(2, 12.0);
  const auto chain = make_motion(Method::SMA, k, {}, Chain::spiral);
  const auto plain = make_motion(Method::SMA, k);
  for (double u = -1.0; u <= 2.0; u += 0.125) {
    const double t = k[0].t + u * (k[1].t - k[0].t);
    EXPECT_TRUE(test::arrows_near(chain->at(t), plain->at(t), 0.0, 1.0, false));
  }
}

}  // namespace
}  // namespace pita
