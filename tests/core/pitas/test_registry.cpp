// The table of arrow methods and how each is built (src/core/pitas/registry.cpp).
// What each PITA does is the property suite of tests/core/test_pitas.cpp;
// here: the table, the checks make_motion makes, and that it builds the
// method it is asked for.
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "../test_support.hpp"
#include "core/pitas/registry.hpp"

namespace pita::test {
namespace {

TEST(Registry, TableListsEachMethodOnce) {
  std::set<std::string> ids;
  std::size_t outside_basket = 0;
  for (const MethodInfo& entry : all_methods()) {
    EXPECT_TRUE(ids.insert(std::string(entry.id)).second) << entry.id;
    EXPECT_EQ(&info(entry.method), &entry) << entry.id;
    EXPECT_EQ(entry.keyframe_count, entry.method == Method::SMA ? 2 : 3) << entry.id;
    if (!entry.in_basket) ++outside_basket;
  }
  // P1-P10, P5S, SMA, the three other combinations of Fig. 7 and the four
  // variants of appendices C and D.
  EXPECT_EQ(ids.size(), 19u);
  EXPECT_EQ(outside_basket, 7u);
  EXPECT_EQ(all_methods().front().method, Method::P1);  // display order
  EXPECT_EQ(info(Method::P6).id, "P6");
  EXPECT_EQ(info(Method::P6).mnemonic, "La-LP");
  EXPECT_FALSE(info(Method::LSLP).in_basket);
}

TEST(Registry, MakeMotionChecksCountKnotsAndValues) {
  const Arrow A{{0.0, 0.0}, 1.0, 0.0}, B{{1.0, 1.0}, 1.0, 0.5}, C{{2.0, 0.0}, 1.0, 1.0};
  const std::vector<Keyframe> three = {{0.0, A}, {0.5, B}, {1.0, C}};
  const std::vector<Keyframe> two = {{0.0, A}, {1.0, C}};
  try {
    make_motion(Method::P6, two);
    FAIL() << "P6 built from two keyframes";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "P6 takes at least 3 keyframes, got 2");
  }
  EXPECT_THROW(make_motion(Method::SMA, std::span(two).first(1)), std::invalid_argument);
  EXPECT_NO_THROW(make_motion(Method::SMA, three));  // a spiral chain (core/chains/chain.hpp)
  EXPECT_THROW(make_motion(Method::P3, std::vector<Keyframe>{{0.0, A}, {0.0, B}, {1.0, C}}), std::invalid_argument);
  EXPECT_THROW(make_motion(Method::P3, std::vector<Keyframe>{{0.0, A}, {1.0, B}, {0.5, C}}), std::invalid_argument);
  EXPECT_THROW(make_motion(Method::P3, std::vector<Keyframe>{{0.0, A}, {0.5, Arrow{{1.0, 1.0}, 0.0, 0.0}}, {1.0, C}}),
               std::invalid_argument);
  EXPECT_THROW(make_motion(Method::P3, std::vector<Keyframe>{{0.0, A}, {std::nan(""), B}, {1.0, C}}),
               std::invalid_argument);
  EXPECT_THROW(make_pita(Method::SMA, KeyframeTriple{three[0], three[1], three[2]}), std::invalid_argument);
}

TEST(Registry, EveryMethodBuildsAMotionThroughItsKeyframes) {
  Sampler s(91);
  for (const MethodInfo& entry : all_methods()) {
    const KeyframeTriple k = s.triple(Config::uneven);
    const std::vector<Keyframe> keyframes =
        entry.keyframe_count == 2 ? std::vector<Keyframe>{k.a, k.c} : std::vector<Keyframe>{k.a, k.b, k.c};
    const auto D = make_motion(entry.method, keyframes);
    ASSERT_NE(D, nullptr) << entry.id;
    for (const Keyframe& key : keyframes) {
      EXPECT_TRUE(arrows_near(D->at(key.t), key.arrow, 1e-9, extent(k), false)) << entry.id << " at " << key.t;
    }
  }
}

// SMA between (1, 0) at winding pi/2 and (-1, 0) at 3 pi/2: the twirl between
// them is the half turn about the origin, so halfway it is the quarter turn:
// p = (0, 1), winding pi (PITA Eq. 21).
TEST(Registry, SmaIsTheSteadyMorphOfItsTwoKeyframes) {
  const double pi = std::numbers::pi;
  const std::vector<Keyframe> keyframes = {{0.0, Arrow{{1.0, 0.0}, 1.0, pi / 2.0}},
                                           {2.0, Arrow{{-1.0, 0.0}, 1.0, 1.5 * pi}}};
  const Arrow mid = make_motion(Method::SMA, keyframes)->at(1.0);
  EXPECT_NEAR(mid.p.real(), 0.0, 1e-15);
  EXPECT_NEAR(mid.p.imag(), 1.0, 1e-15);
  EXPECT_NEAR(mid.m, 1.0, 1e-15);
  EXPECT_NEAR(mid.w, pi, 1e-15);
}

// P1 (Pa-Ca) is the Lagrange interpolation of p and of the vector q - p
// (PITA Eq. 11): make_motion must build that method and not another.
TEST(Registry, P1IsTheLagrangeInterpolantOfPointAndVector) {
  const Arrow A{{0.0, 0.0}, 1.0, 0.0}, B{{1.0, 2.0}, 2.0, std::numbers::pi / 2.0}, C{{3.0, 0.0}, 1.0, 0.0};
  const auto D = make_motion(Method::P1, std::vector<Keyframe>{{0.0, A}, {1.0, B}, {2.0, C}});
  // At t = 1/2: weights 3/8, 3/4, -1/8.
  const Arrow half = D->at(0.5);
  EXPECT_NEAR(half.p.real(), 0.75 - 0.375, 1e-14);
  EXPECT_NEAR(half.p.imag(), 1.5, 1e-14);
  const Point vector = half.q() - half.p;  // 3/8 (1, 0) + 3/4 (0, 2) - 1/8 (1, 0)
  EXPECT_NEAR(vector.real(), 0.25, 1e-14);
  EXPECT_NEAR(vector.imag(), 1.5, 1e-14);
}

}  // namespace
}  // namespace pita::test
