// The "blend" chain (core/chains/blend_chain.hpp): through every keyframe,
// C1 at every interior knot, the method itself for three keyframes, the
// formula of docs/paper-notes.md N33 on four, similarity-invariant with the
// method, and smooth past both ends.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "core/chains/blend_chain.hpp"
#include "core/pitas/registry.hpp"
#include "core/steady_morph.hpp"
#include "track_support.hpp"

namespace pita {
namespace {

using test::TrackSampler;

// The chain, or nullptr when the method has no motion through some triple
// (the -Pe methods refuse isolated configurations).
std::unique_ptr<Motion> chain_or_null(Method m, const std::vector<Keyframe>& keys, Chain chain) {
  try {
    return make_motion(m, keys, {}, chain);
  } catch (const MotionDomainError&) {
    return nullptr;
  }
}

class BlendChainOf : public ::testing::TestWithParam<Method> {};

TEST_P(BlendChainOf, PassesEveryKeyframeAndIsC1AtInteriorKnots) {
  const Method m = GetParam();
  const bool modulo = !info(m).winding_aware;
  TrackSampler s(1000 + static_cast<int>(m));
  int checked = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const bool wild = trial % 2 == 1;
    const std::vector<Keyframe> keys = s.track(s.integer(4, 12), wild ? 9.0 : 2.0, wild ? 2.3 : 0.7);
    const auto motion = chain_or_null(m, keys, Chain::blend);
    if (!motion) continue;
    ++checked;
    const double size = test::extent(keys);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      EXPECT_TRUE(test::arrows_near(motion->at(keys[i].t), keys[i].arrow, 1e-9, size, modulo))
          << test::name(m) << " trial " << trial << " keyframe " << i;
    }
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
      const double gap = std::min(keys[i].t - keys[i - 1].t, keys[i + 1].t - keys[i].t);
      const double jump = test::velocity_jump(*motion, keys[i].t, 1e-4 * gap, size / gap);
      EXPECT_LT(jump, 1e-5) << test::name(m) << " trial " << trial << " knot " << i << " of " << keys.size();
    }
  }
  EXPECT_GE(checked, 18) << "too few tracks had a motion";
}

TEST_P(BlendChainOf, IsTheMethodItselfForThreeKeyframes) {
  const Method m = GetParam();
  TrackSampler s(2000 + static_cast<int>(m));
  for (int trial = 0; trial < 6; ++trial) {
    const std::vector<Keyframe> keys = s.track(3);
    const auto chain = chain_or_null(m, keys, Chain::blend);
    if (!chain) continue;
    const auto plain = make_pita(m, {keys[0], keys[1], keys[2]});
    for (double u = -0.5; u <= 1.5; u += 0.0625) {
      const double t = keys[0].t + u * (keys[2].t - keys[0].t);
      EXPECT_TRUE(test::arrows_near(chain->at(t), plain->at(t), 1e-12, test::extent(keys), false))
          << test::name(m) << " t = " << t;
    }
  }
}

TEST_P(BlendChainOf, OnFourKeyframesIsTheSteadyBlendOfTheTwoTriples) {
  const Method m = GetParam();
  TrackSampler s(3000 + static_cast<int>(m));
  const std::vector<Keyframe> keys = s.track(4);
  const auto chain = chain_or_null(m, keys, Chain::blend);
  if (!chain) GTEST_SKIP() << "no motion";
  const auto X = make_pita(m, {keys[0], keys[1], keys[2]});
  const auto Y = make_pita(m, {keys[1], keys[2], keys[3]});
  const double size = test::extent(keys);
  for (double u = -0.5; u <= 1.5; u += 0.125) {
    // Span 0 and before: X alone; span 2 and after: Y alone; span 1: the blend.
    const double t0 = keys[0].t + u * (keys[1].t - keys[0].t);
    const double t2 = keys[2].t + (u + 0.5) * (keys[3].t - keys[2].t);
    EXPECT_TRUE(
        test::arrows_near(chain->at(std::min(t0, keys[1].t)), X->at(std::min(t0, keys[1].t)), 1e-12, size, false));
    EXPECT_TRUE(test::arrows_near(chain->at(t2), Y->at(t2), 1e-12, size, false));
  }
  for (double s1 = 0.0; s1 <= 1.0; s1 += 0.125) {
    const double t = keys[1].t + s1 * (keys[2].t - keys[1].t);
    const Arrow expected = test::blend_of(X->at(t), Y->at(t), s1, info(m).winding_aware);
    EXPECT_TRUE(test::arrows_near(chain->at(t), expected, 1e-10, size, false)) << "s = " << s1;
  }
}

TEST_P(BlendChainOf, IsSimilarityInvariantWhenTheMethodIs) {
  const Method m = GetParam();
  if (m == Method::P5) GTEST_SKIP() << "P5 is translation-invariant only (docs/paper-notes.md N7)";
  if (m == Method::P10) GTEST_SKIP() << "P10's principal logs are not rotation-invariant (docs/paper-notes.md N6)";
  TrackSampler s(4000 + static_cast<int>(m));
  for (int trial = 0; trial < 6; ++trial) {
    const std::vector<Keyframe> keys = s.track(s.integer(4, 9));
    const Twirl S = twirl(Point{s.uniform(-3, 3), s.uniform(-3, 3)}, std::exp(s.uniform(-1, 1)), s.uniform(-3, 3));
    const auto original = chain_or_null(m, keys, Chain::blend);
    const auto image = chain_or_null(m, test::moved(S, keys), Chain::blend);
    if (!original || !image) continue;
    for (double u = -0.2; u <= 1.2; u += 0.05) {
      const double t = keys.front().t + u * (keys.back().t - keys.front().t);
      const Arrow expected = S * original->at(t);
      if (!(expected.m > 0.0 && is_finite(expected))) continue;  // P2 past the ends: m < 0, no frame
      // Far outside the knots values grow (the methods extrapolate): compare
      // relative to the frame's own size there.
      const double size = std::max({test::extent(test::moved(S, keys)), std::abs(expected.p), std::abs(expected.q())});
      EXPECT_TRUE(test::arrows_near(image->at(t), expected, 1e-8, size, !info(m).winding_aware))
          << test::name(m) << " trial " << trial << " t = " << t;
    }
  }
}

TEST_P(BlendChainOf, ContinuesSmoothlyPastBothEnds) {
  const Method m = GetParam();
  TrackSampler s(5000 + static_cast<int>(m));
  const std::vector<Keyframe> keys = s.track(7);
  const auto motion = chain_or_null(m, keys, Chain::blend);
  if (!motion) GTEST_SKIP() << "no motion";
  const double size = test::extent(keys);
  for (const std::size_t end : {std::size_t{0}, keys.size() - 1}) {
    const double t = keys[end].t;
    const double gap = end == 0 ? keys[1].t - keys[0].t : keys[end].t - keys[end - 1].t;
    const bool modulo = !info(m).winding_aware;
    EXPECT_TRUE(test::arrows_near(motion->at(t + 1e-9 * gap), keys[end].arrow, 1e-6, size, modulo));
    EXPECT_TRUE(test::arrows_near(motion->at(t - 1e-9 * gap), keys[end].arrow, 1e-6, size, modulo));
    EXPECT_LT(test::velocity_jump(*motion, t, 1e-4 * gap, size / gap), 1e-5) << "end " << end;
    // Past the end it is the end triple's own motion.
    const std::size_t first = end == 0 ? 0 : end - 2;
    const auto triple = make_pita(m, {keys[first], keys[first + 1], keys[first + 2]});
    const double beyond = end == 0 ? t - 0.7 * gap : t + 0.7 * gap;
    EXPECT_TRUE(test::arrows_near(motion->at(beyond), triple->at(beyond), 1e-12, size, false));
  }
}

INSTANTIATE_TEST_SUITE_P(EveryPita, BlendChainOf, ::testing::ValuesIn(test::pitas()),
                         [](const auto& param) { return test::name(param.param); });

// The C1 measure above can fail: the spiral chain, C0 by construction, has
// velocity jumps far above its tolerance at almost every knot.
TEST(BlendChainControl, TheC1MeasureSeesTheSpiralChainsKinks) {
  TrackSampler s(6000);
  int kinks = 0, knots = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<Keyframe> keys = s.track(6);
    const auto spiral = make_motion(Method::P6, keys, {}, Chain::spiral);
    for (std::size_t i = 1; i + 1 < keys.size(); ++i, ++knots) {
      const double gap = std::min(keys[i].t - keys[i - 1].t, keys[i + 1].t - keys[i].t);
      if (test::velocity_jump(*spiral, keys[i].t, 1e-4 * gap, test::extent(keys) / gap) > 1e-3) ++kinks;
    }
  }
  EXPECT_GE(kinks, knots * 9 / 10) << kinks << " of " << knots;
}

}  // namespace
}  // namespace pita
