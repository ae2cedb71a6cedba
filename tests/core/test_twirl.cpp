// Twirls (PITA Eq. 5-8) and the twirl between two arrows (PITA Eq. 17-19), checked
// against plain complex arithmetic f + m e^{iw}(x - f) as the oracle.
#include "core/twirl.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

TEST(Twirl, ActsAsSimilarityAboutItsFixedPoint) {
  Sampler s(1);
  for (int i = 0; i < 200; ++i) {
    const Point f = s.point();
    const double m = std::exp(s.uniform(-1, 1));
    const double w = s.uniform(-10, 10);
    const Twirl T = twirl(f, m, w);
    const Point x = s.point();
    const Point oracle = f + std::polar(m, w) * (x - f);  // PITA Eq. 2-5
    EXPECT_NEAR(std::abs((T * x) - oracle), 0.0, 1e-12);
    const Arrow A = s.arrow(Config::wild);
    const Arrow TA = T * A;  // PITA Eq. 7
    EXPECT_NEAR(std::abs(TA.p - (f + std::polar(m, w) * (A.p - f))), 0.0, 1e-12);
    EXPECT_NEAR(TA.m, m * A.m, 1e-12 * TA.m);
    EXPECT_NEAR(TA.w, A.w + w, 1e-12);
    // PITA Eq. 8: T^t = T(f, m^t, t w).
    const double t = s.uniform(-2, 2);
    const Point oracle_t = f + std::polar(std::pow(m, t), t * w) * (x - f);
    EXPECT_NEAR(std::abs((pow(T, t) * x) - oracle_t), 0.0, 1e-11);
  }
}

TEST(Twirl, BetweenMapsFirstArrowOntoSecond) {
  Sampler s(2);
  for (int i = 0; i < 500; ++i) {
    const Arrow A = s.arrow(Config::wild);
    const Arrow B = s.arrow(Config::wild);
    const Twirl T = twirl_between(A, B);
    EXPECT_TRUE(arrows_near(T * A, B, 1e-12, 1.0 + std::abs(B.p), false)) << i;
    EXPECT_TRUE(arrows_near(apply_power(T, 1.0, A), B, 1e-12, 1.0 + std::abs(B.p), false)) << i;
    EXPECT_TRUE(arrows_near(apply_power(T, 0.0, A), A, 1e-15, 1.0 + std::abs(A.p), false)) << i;
  }
}

TEST(Twirl, FixedPointIsFixedAndMatchesEq19) {
  Sampler s(3);
  for (int i = 0; i < 200; ++i) {
    const Arrow A = s.arrow(Config::tame);
    const Arrow B = s.arrow(Config::tame);
    const Twirl T = twirl_between(A, B);
    const auto f = fixed_point(T);
    ASSERT_TRUE(f.has_value());
    EXPECT_NEAR(std::abs((T * *f) - *f), 0.0, 1e-10 * (1 + std::abs(*f)));
    // docs/paper-notes.md N1: f = (B.p - lambda A.p) / (1 - lambda), lambda = m e^{iw}.
    const Complex lambda = std::polar(B.m / A.m, B.w - A.w);
    EXPECT_NEAR(std::abs(*f - (B.p - lambda * A.p) / (1.0 - lambda)), 0.0, 1e-10 * (1 + std::abs(*f)));
  }
}

TEST(Twirl, PowersCompose) {
  // T^s . T^t = T^{s+t} and (T^t)^s = T^{st}.
  Sampler s(4);
  for (int i = 0; i < 300; ++i) {
    const Twirl T = twirl_between(s.arrow(Config::wild), s.arrow(Config::wild));
    const double a = s.uniform(-1.5, 1.5), b = s.uniform(-1.5, 1.5);
    const Point x = s.point();
    const Point lhs = pow(T, a) * (pow(T, b) * x);
    const Point rhs = pow(T, a + b) * x;
    const double scale = 1.0 + std::abs(rhs) + std::abs(T.displacement()) * 10;
    EXPECT_NEAR(std::abs(lhs - rhs), 0.0, 1e-10 * scale) << i;
    EXPECT_NEAR(std::abs((pow(pow(T, a), b) * x) - (pow(T, a * b) * x)), 0.0, 1e-10 * scale);
    EXPECT_NEAR(std::abs((compose(pow(T, a), pow(T, b)) * x) - rhs), 0.0, 1e-10 * scale);
  }
}

TEST(Twirl, InverseUndoes) {
  Sampler s(5);
  for (int i = 0; i < 200; ++i) {
    const Twirl T = twirl_between(s.arrow(Config::wild), s.arrow(Config::wild));
    const Point x = s.point();
    EXPECT_NEAR(std::abs(inverse(T) * (T * x) - x), 0.0, 1e-9 * (1 + std::abs(x)));
  }
}

// The translation fallback of Sec. 2.5 (limits::kTwirlTranslation): frames of
// the steady morph are continuous when the twirl's log crosses the threshold.
TEST(Twirl, TranslationFallbackIsContinuousAcrossItsThreshold) {
  const Arrow A{{0.0, 0.0}, 1.0, 0.3};
  const double thr = limits::kTwirlTranslation;
  for (double t : {-0.5, 0.25, 0.5, 0.9, 1.7}) {
    // |e^L - 1| ~ |L| just above and just below the threshold, in several directions.
    for (double dir : {0.0, 0.7, 1.5707963, 2.5}) {
      const Complex above = std::polar(thr * 1.01, dir);
      const Complex below = std::polar(thr * 0.99, dir);
      const auto frame = [&](Complex L) {
        const Arrow B{{3.0, 1.0}, A.m * std::exp(L.real()), A.w + L.imag()};
        return apply_power(twirl_between(A, B), t, A);
      };
      const Arrow x = frame(above), y = frame(below);
      EXPECT_LT(frame_distance(x, y), 1e-11) << "t=" << t << " dir=" << dir;
      // Both are the translation by t (B.p - A.p) up to the threshold.
      EXPECT_LT(std::abs(x.p - Point{3.0 * t, 1.0 * t}), 1e-11);
    }
  }
  // Exactly equal vectors: a pure translation (PITA Eq. 15).
  const Arrow B{{2.0, -1.0}, 1.0, 0.3};
  const Arrow mid = apply_power(twirl_between(A, B), 0.5, A);
  EXPECT_EQ(mid.p, (Point{1.0, -0.5}));
  EXPECT_EQ(mid.m, 1.0);
  EXPECT_EQ(mid.w, 0.3);
}

TEST(Twirl, FullTurnWithoutFixedPointSpinsAboutTheMovingOrigin) {
  // Equal magnitudes, windings a whole turn apart, distinct origins: no twirl
  // maps A onto B (limits.hpp); the fallback moves the origin on the segment
  // and spins the vector, and still reaches B.
  const Arrow A{{0.0, 0.0}, 1.0, 0.0};
  const Arrow B{{4.0, 0.0}, 1.0, 2.0 * kPi};
  const Twirl T = twirl_between(A, B);
  EXPECT_FALSE(fixed_point(T).has_value());
  const Arrow half = apply_power(T, 0.5, A);
  EXPECT_NEAR(std::abs(half.p - Point{2.0, 0.0}), 0.0, 1e-12);
  EXPECT_NEAR(half.w, kPi, 1e-12);
  EXPECT_TRUE(arrows_near(apply_power(T, 1.0, A), B, 1e-12, 4.0, false));
}

TEST(Twirl, ExpOfLogIsTheTwirlAndExpOfTLogIsItsPower) {
  const Arrow A{{1.0, 2.0}, 0.8, 0.3}, B{{-2.0, 0.5}, 1.9, 2.6};
  const Twirl T = twirl_between(A, B);
  const TwirlLog G = log(T);
  for (const Point x : {Point{0.0, 0.0}, Point{3.0, -1.0}, A.p}) {
    EXPECT_NEAR(std::abs(pita::apply(exp(G), x) - pita::apply(T, x)), 0.0, 1e-13) << x;
    for (const double t : {-0.7, 0.25, 0.5, 1.8}) {
      EXPECT_NEAR(std::abs(pita::apply(exp(TwirlLog{t * G.L, t * G.v}), x) - apply_power(T, t, x)), 0.0, 1e-12)
          << "t = " << t << ", x = " << x;
    }
  }
  // The generator's velocity field vanishes at the fixed point (PITA Eq. 19).
  const Point f = *fixed_point(T);
  EXPECT_NEAR(std::abs(G.L * f + G.v), 0.0, 1e-13);
}

TEST(Twirl, LogOfATranslationIsItsDisplacement) {
  const Twirl T = translation(Vector{3.0, -4.0});
  const TwirlLog G = log(T);
  EXPECT_EQ(G.L, Complex{});
  EXPECT_NEAR(std::abs(G.v - Vector{3.0, -4.0}), 0.0, 1e-15);
  EXPECT_NEAR(std::abs(pita::apply(exp(G), Point{1.0, 1.0}) - Point{4.0, -3.0}), 0.0, 1e-15);
  EXPECT_EQ(pita::apply(inverse(T), pita::apply(T, Point{2.0, 5.0})), Point(2.0, 5.0));
}

}  // namespace
}  // namespace pita::test
