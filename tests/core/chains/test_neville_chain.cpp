// The "neville" chain (core/chains/neville_chain.hpp): PITA Eq. 48-50 on arrows
// for four keyframes, the hand-written recursion for five, P9 for the SMA on
// three, through every keyframe and smooth everywhere.
#include <gtest/gtest.h>

#include "../test_support.hpp"
#include "core/chains/neville_chain.hpp"
#include "core/pitas/registry.hpp"
#include "core/steady_morph.hpp"
#include "track_support.hpp"

namespace pita {
namespace {

using test::TrackSampler;

std::unique_ptr<Motion> neville_or_null(Method m, const std::vector<Keyframe>& keys) {
  try {
    return make_motion(m, keys, {}, Chain::neville);
  } catch (const MotionDomainError&) {
    return nullptr;
  }
}

class NevilleChainOf : public ::testing::TestWithParam<Method> {};

TEST_P(NevilleChainOf, OnFourKeyframesIsEq48To50OnArrows) {
  const Method m = GetParam();
  TrackSampler s(7000 + static_cast<int>(m));
  const std::vector<Keyframe> keys = s.track(4, 2.0, 0.5, 0.4);
  const auto chain = neville_or_null(m, keys);
  if (!chain) GTEST_SKIP() << "no motion";
  const auto X = make_pita(m, {keys[0], keys[1], keys[2]});  // PITA Eq. 48
  const auto Y = make_pita(m, {keys[1], keys[2], keys[3]});  // PITA Eq. 49
  int compared = 0;
  for (double u = -0.25; u <= 1.25; u += 0.0625) {
    const double t = keys[0].t + u * (keys[3].t - keys[0].t);
    const Arrow x = X->at(t), y = Y->at(t);
    // Windows evaluated away from their knots may leave the method's domain
    // (P2's polar magnitude turns negative): nothing to compare there, except
    // at the ends, where the chain is exactly X or Y.
    if (u == 0.0) {
      EXPECT_TRUE(test::arrows_near(chain->at(t), x, 0.0, 1.0, false));
    }
    if (u == 1.0) {
      EXPECT_TRUE(test::arrows_near(chain->at(t), y, 0.0, 1.0, false));
    }
    if (!(x.m > 0.0 && y.m > 0.0 && is_finite(x) && is_finite(y))) continue;
    ++compared;
    const Arrow expected = test::blend_of(x, y, u, info(m).winding_aware);  // PITA Eq. 50, M for the blend
    EXPECT_TRUE(test::arrows_near(chain->at(t), expected, 1e-10, test::extent(keys), !info(m).winding_aware))
        << "u = " << u;
  }
  EXPECT_GE(compared, 13);
}

TEST_P(NevilleChainOf, PassesEveryKeyframeAndIsSmooth) {
  const Method m = GetParam();
  TrackSampler s(8000 + static_cast<int>(m));
  int checked = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const bool wild = trial % 2 == 1;
    // Neville is global: its bottom windows are evaluated over the whole
    // track, far from their own knots, so tracks are kept near even here
    // (docs/reference/scene-format.md "Keyframe tracks": prefer "blend" for uneven or long tracks).
    const std::vector<Keyframe> keys = s.track(s.integer(4, 6), wild ? 4.0 : 2.0, wild ? 1.2 : 0.5, 0.4);
    const auto motion = neville_or_null(m, keys);
    if (!motion) continue;
    ++checked;
    const double size = test::extent(keys);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      EXPECT_TRUE(test::arrows_near(motion->at(keys[i].t), keys[i].arrow, 1e-9, size, !info(m).winding_aware))
          << test::name(m) << " trial " << trial << " keyframe " << i;
    }
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
      const double gap = std::min(keys[i].t - keys[i - 1].t, keys[i + 1].t - keys[i].t);
      const double jump = test::velocity_jump(*motion, keys[i].t, 1e-4 * gap, size / gap);
      // P2's polar magnitude is Lagrange-interpolated, so a window evaluated
      // far from its knots can have m < 0: the chain has no frame there
      // (docs/reference/scene-format.md "Keyframe tracks"). Every other PITA must be defined.
      if (m == Method::P2 && !std::isfinite(jump)) continue;
      EXPECT_LT(jump, 1e-4) << test::name(m) << " trial " << trial << " knot " << i;
    }
  }
  EXPECT_GE(checked, 9);
}

INSTANTIATE_TEST_SUITE_P(EveryPita, NevilleChainOf, ::testing::ValuesIn(test::pitas()),
                         [](const auto& param) { return test::name(param.param); });

TEST(NevilleChain, OnFiveKeyframesIsTheHandWrittenRecursion) {
  TrackSampler s(8500);
  const std::vector<Keyframe> k = s.track(5, 2.0, 0.5, 0.4);
  const auto chain = make_motion(Method::P6, k, {}, Chain::neville);
  const auto T0 = make_pita(Method::P6, {k[0], k[1], k[2]});
  const auto T1 = make_pita(Method::P6, {k[1], k[2], k[3]});
  const auto T2 = make_pita(Method::P6, {k[2], k[3], k[4]});
  for (double u = -0.2; u <= 1.2; u += 0.05) {
    const double t = k[0].t + u * (k[4].t - k[0].t);
    const Arrow L = steady_morph(T0->at(t), T1->at(t), (t - k[0].t) / (k[3].t - k[0].t));
    const Arrow R = steady_morph(T1->at(t), T2->at(t), (t - k[1].t) / (k[4].t - k[1].t));
    const Arrow expected = steady_morph(L, R, (t - k[0].t) / (k[4].t - k[0].t));
    EXPECT_TRUE(test::arrows_near(chain->at(t), expected, 1e-10, test::extent(k), false)) << "u = " << u;
  }
}

// With the SMA at the bottom, Neville over three keyframes is P9 (PITA Eq. D.2),
// which core/pitas/p09_ne_lp.cpp computes on its own.
TEST(NevilleChain, OfTheSmaOnThreeKeyframesIsP9) {
  TrackSampler s(8600);
  for (int trial = 0; trial < 8; ++trial) {
    const std::vector<Keyframe> k = s.track(3, 9.0, 2.0);
    const auto chain = make_motion(Method::SMA, k, {}, Chain::neville);
    const auto p9 = make_pita(Method::P9, {k[0], k[1], k[2]});
    for (double u = -0.5; u <= 1.5; u += 0.0625) {
      const double t = k[0].t + u * (k[2].t - k[0].t);
      EXPECT_TRUE(test::arrows_near(chain->at(t), p9->at(t), 1e-10, test::extent(k), false)) << "u = " << u;
    }
  }
}

TEST(NevilleChain, IsSimilarityInvariantWithP6) {
  TrackSampler s(8700);
  const std::vector<Keyframe> keys = s.track(6, 2.0, 0.5, 0.4);
  const Twirl S = twirl(Point{1.5, -2.0}, 2.5, 2.0);
  const auto original = make_motion(Method::P6, keys, {}, Chain::neville);
  const auto image = make_motion(Method::P6, test::moved(S, keys), {}, Chain::neville);
  for (double u = -0.2; u <= 1.2; u += 0.05) {
    const double t = keys.front().t + u * (keys.back().t - keys.front().t);
    const Arrow expected = S * original->at(t);
    const double size = std::max({test::extent(test::moved(S, keys)), std::abs(expected.p), std::abs(expected.q())});
    EXPECT_TRUE(test::arrows_near(image->at(t), expected, 1e-8, size, false));
  }
}

}  // namespace
}  // namespace pita
