// The measurements behind pita audit, on configurations whose answer is
// known from the paper or by hand.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "analysis/audit_configs.hpp"
#include "analysis/properties.hpp"

namespace pita::analysis {
namespace {

KeyframeTriple tame() { return {{0.0, {{0, 0}, 1.0, 0.4}}, {0.5, {{3, 1.5}, 0.6, 2.0}}, {1.0, {{6, 0}, 1.2, 3.5}}}; }

TEST(Properties, TableIsComplete) {
  EXPECT_EQ(all_properties().size(), 13u);
  for (const PropertyInfo& p : all_properties()) {
    EXPECT_EQ(find_property(p.id), &p);
    EXPECT_FALSE(p.measure.empty());
  }
  EXPECT_EQ(find_property("nonsense"), nullptr);
}

TEST(Properties, SimilarityActsOnArrowsAsAComplexMap) {
  // Independent: rotate by 90 degrees, scale by 2, shift by (1, 0).
  const Similarity S{{1.0, 0.0}, 2.0, kPi / 2};
  const Arrow A = apply(S, Arrow{{1.0, 0.0}, 1.0, 7.0});
  EXPECT_NEAR(A.p.real(), 1.0, 1e-15);
  EXPECT_NEAR(A.p.imag(), 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(A.m, 2.0);
  EXPECT_DOUBLE_EQ(A.w, 7.0 + kPi / 2);  // windings gain the rotation, unreduced
}

TEST(Properties, SimilarityInvarianceSeparatesP6FromP5) {
  // P6 is similarity-invariant (Sec. 4.3); P5 is not (notes N7).
  double p6 = 0, p5 = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    p6 = std::max(p6, probe(Property::similarity_invariant, Method::P6, tame(), seed).value);
    p5 = std::max(p5, probe(Property::similarity_invariant, Method::P5, tame(), seed).value);
  }
  EXPECT_LT(p6, 1e-10);
  EXPECT_GT(p5, 1e-4);
}

TEST(Properties, PopsAtPtwosCutAndNotForPone) {
  // Fig. 12: origins collinear with c behind b; a 1e-9 tweak flips P2's spiral.
  const KeyframeTriple cut{{0.0, {{0, 0}, 1.0, 1.0}}, {0.5, {{2, 0}, 0.8, 1.6}}, {1.0, {{0.5, 0}, 1.2, 2.2}}};
  const Probe p2 = probe(Property::pop_free, Method::P2, cut, 1);
  EXPECT_GT(p2.value, 1e-3);
  ASSERT_TRUE(p2.counterpart.has_value());
  EXPECT_LT(probe(Property::pop_free, Method::P1, cut, 1).value, 1e-12);
}

TEST(Properties, KnotRatioMovesTheCurveOfP1ButNotOfP2) {
  // Fig. 13: P2's point stays on its log spiral when b moves.
  EXPECT_GT(probe(Property::knot_controlled, Method::P1, tame(), 1).value, 1e-3);
  EXPECT_LT(probe(Property::knot_controlled, Method::P2, tame(), 1).value, 1e-9);
}

TEST(Properties, AWholeTurnOfAKeyframeChangesP6ButNotP1) {
  EXPECT_GT(probe(Property::winding_aware, Method::P6, tame(), 1).value, 1e-3);
  EXPECT_LT(probe(Property::winding_aware, Method::P1, tame(), 1).value, 1e-12);
}

TEST(Properties, PerseveranceOfP1P7P8) {
  // Sec. 3.3: P1 global, P7 radial, P8 local.
  EXPECT_LT(probe(Property::globally_perseverant, Method::P1, tame(), 1).value, 1e-6);
  EXPECT_LT(probe(Property::radially_perseverant, Method::P7, tame(), 1).value, 1e-6);
  EXPECT_LT(probe(Property::locally_perseverant, Method::P8, tame(), 1).value, 1e-6);
  EXPECT_GT(probe(Property::globally_perseverant, Method::P6, tame(), 1).value, 1e-3);
  EXPECT_GT(probe(Property::locally_perseverant, Method::P7, tame(), 1).value, 1e-3);
}

TEST(Properties, SecondDerivativeJumpsAtAnUnevenKnotForP8NotP6) {
  const KeyframeTriple uneven{{0.0, {{0, 0}, 1.0, 0.3}}, {0.2, {{1.5, 2.0}, 2.0, 1.4}}, {1.0, {{6, 0}, 0.6, -0.8}}};
  EXPECT_GT(probe(Property::smooth, Method::P8, uneven, 1).value, 1e-2);
  EXPECT_LT(probe(Property::smooth, Method::P6, uneven, 1).value, 1e-4);
}

TEST(Properties, ExistenceReportsAMotionThatCannotBeBuilt) {
  // A keyframe without magnitude has no log: the log-polar methods cannot be
  // built (or give no finite frame); the Cartesian P1 can.
  const KeyframeTriple none{{0.0, {{0, 0}, 1.0, 0.0}}, {0.5, {{2, 1}, 0.0, 0.0}}, {1.0, {{4, 0}, 1.0, 0.0}}};
  const Probe p = probe(Property::exists, Method::P6, none, 1);
  EXPECT_EQ(p.value, 1.0);
  EXPECT_FALSE(p.note.empty());
  EXPECT_EQ(probe(Property::exists, Method::P1, none, 1).value, 0.0);
  EXPECT_EQ(probe(Property::exists, Method::P1, tame(), 1).value, 0.0);
}

}  // namespace
}  // namespace pita::analysis
