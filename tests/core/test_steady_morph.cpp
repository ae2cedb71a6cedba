// Steady morph, steady average and steady transport (Sec. 2.5-2.7).
#include "core/steady_morph.hpp"
#include "core/steady_transport.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

TEST(SteadyMorph, ReachesEndpoints) {
  Sampler s(10);
  for (int i = 0; i < 300; ++i) {
    const Arrow A = s.arrow(Config::wild), B = s.arrow(Config::wild);
    EXPECT_TRUE(arrows_near(steady_morph(A, B, 0.0), A, 1e-14, 10.0, false));
    EXPECT_TRUE(arrows_near(steady_morph(A, B, 1.0), B, 1e-12, 10.0, false));
    EXPECT_TRUE(arrows_near(steady_morph(2.0, A, 5.0, B, 5.0), B, 1e-12, 10.0, false));
  }
}

TEST(SteadyMorph, FarExtrapolatedStartStillEndsExactlyOnB) {
  // Evaluated from the nearer end (docs/paper-notes.md N36): M(X, B, 1) is B
  // to the last bit, however far X is (P9 extrapolates its Neville steps to
  // arrows 1e14 times the figure's size).
  const Arrow B{{0.9330277525731567, 4.754893251147427}, 10.983615097998593, 4.327661974202112};
  const Arrow X{{3.1e13, -2.2e13}, 4.0e14, -31.7};
  const Arrow at_one = steady_morph(X, B, 1.0);
  EXPECT_EQ(at_one.p, B.p);
  EXPECT_EQ(at_one.m, B.m);
  EXPECT_EQ(at_one.w, B.w);
  // And close to B the frames are accurate relative to B, not to X: a small
  // step from B along the morph (checked against the morph taken from X, to
  // the rounding of X's size).
  const Arrow near_one = steady_morph(X, B, 1.0 - 1e-9);
  EXPECT_LT(std::abs(near_one.p - B.p), 1e7);  // 1e-9 of the way back to X
  EXPECT_TRUE(std::isfinite(near_one.p.real()));
}

TEST(SteadyMorph, IsSymmetric) {
  // PITA Eq. 22: M(a, A, b, B, t) = M(b, B, a, A, t).
  Sampler s(11);
  for (int i = 0; i < 300; ++i) {
    const Arrow A = s.arrow(Config::wild), B = s.arrow(Config::wild);
    const double t = s.uniform(-1, 2);
    EXPECT_TRUE(arrows_near(steady_morph(0.0, A, 1.0, B, t), steady_morph(1.0, B, 0.0, A, t), 1e-10, 10.0, false)) << i;
  }
}

TEST(SteadyAverage, IsSymmetric) {
  Sampler s(12);
  for (int i = 0; i < 300; ++i) {
    const Arrow A = s.arrow(Config::wild), B = s.arrow(Config::wild);
    EXPECT_TRUE(arrows_near(steady_average(A, B), steady_average(B, A), 1e-11, 10.0, false));
  }
}

TEST(SteadyMorph, IsSteady) {
  // Consecutive frames are related by one constant similarity (Fig. 3): the
  // twirl between D(t) and D(t + h) does not depend on t.
  Sampler s(13);
  for (int i = 0; i < 100; ++i) {
    const Arrow A = s.arrow(Config::tame), B = s.arrow(Config::tame);
    const double h = 0.1;
    const Twirl T0 = twirl_between(steady_morph(A, B, 0.0), steady_morph(A, B, h));
    for (double t : {0.2, 0.55, 1.3}) {
      const Twirl T = twirl_between(steady_morph(A, B, t), steady_morph(A, B, t + h));
      EXPECT_NEAR(std::abs(T.log() - T0.log()), 0.0, 1e-12);
      const Point x = s.point();
      EXPECT_NEAR(std::abs((T * x) - (T0 * x)), 0.0, 1e-9);
    }
  }
}

TEST(SteadyMorph, IsSimilarityCovariant) {
  Sampler s(14);
  for (int i = 0; i < 200; ++i) {
    const Arrow A = s.arrow(Config::wild), B = s.arrow(Config::wild);
    const Twirl S = twirl(s.point(), std::exp(s.uniform(-1, 1)), s.uniform(-7, 7));
    const double t = s.uniform(-1, 2);
    EXPECT_TRUE(arrows_near(steady_morph(S * A, S * B, t), S * steady_morph(A, B, t), 1e-9, 10.0, false));
  }
}

TEST(SteadyTransport, MovesByTheMorphSimilarity) {
  // T(C, A, B, t) = T_{A, M(A,B,t)} . C (PITA Eq. 24): the similarity that carries A
  // to the morph frame carries C along.
  Sampler s(15);
  for (int i = 0; i < 200; ++i) {
    const Arrow A = s.arrow(Config::tame), B = s.arrow(Config::tame), C = s.arrow(Config::tame);
    const double t = s.uniform(-1, 2);
    const Arrow via_frame = twirl_between(A, steady_morph(A, B, t)) * C;
    // Windings: the twirl A -> M(A,B,t) has winding t (B.w - A.w) exactly.
    EXPECT_TRUE(arrows_near(steady_transport(C, A, B, t), via_frame, 1e-9, 10.0, false));
    EXPECT_TRUE(arrows_near(steady_transport(A, A, B, t), steady_morph(A, B, t), 1e-12, 10.0, false));
    EXPECT_TRUE(arrows_near(steady_transport(C, 1.0, A, 3.0, B, 1.0 + 2.0 * t), steady_transport(C, A, B, t), 1e-12,
                            10.0, false));
  }
}

}  // namespace
}  // namespace pita::test
