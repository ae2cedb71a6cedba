// The -Pe machinery of P7/P8 (docs/paper-notes.md N13).
#include "core/perseverant.hpp"
#include "core/pitas/motion.hpp"
#include "test_support.hpp"

namespace pita::test {
namespace {

TEST(Perseverant, VectorMotionSolvesTheBoundaryValueProblem) {
  Sampler s(30);
  for (int i = 0; i < 300; ++i) {
    const Vector va = s.arrow(Config::tame).vector(), vb = s.arrow(Config::tame).vector(),
                 vc = s.arrow(Config::tame).vector();
    const Perseverant pe(va, vb, vc);
    EXPECT_NEAR(std::abs(pe.vector_at(-1.0) - va), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(pe.vector_at(0.0) - vb), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(pe.vector_at(1.0) - vc), 0.0, 1e-12);
    // v'' = K v with K = k^2, by finite differences.
    const double h = 1e-3;
    for (double tau : {-0.7, 0.1, 0.8, 1.6}) {
      const Vector acc = (pe.vector_at(tau + h) - 2.0 * pe.vector_at(tau) + pe.vector_at(tau - h)) / (h * h);
      EXPECT_NEAR(std::abs(acc - pe.k() * pe.k() * pe.vector_at(tau)), 0.0, 1e-5 * (1 + std::abs(acc)));
    }
  }
}

TEST(Perseverant, SeriesAndClosedFormAgreeAtTheSwitch) {
  // limits::kPerseverantSeries switches between the power series in K and the
  // closed forms; at the switch both forms must give the same values, so the
  // functions stay continuous there.
  for (double dir : {0.0, 0.9, 2.0, 3.0}) {
    for (double tau : {0.3, 1.0, 1.9, -1.4}) {
      const double K_abs = limits::kPerseverantSeries / std::max(1.0, tau * tau);
      const Complex k = std::sqrt(std::polar(K_abs, dir));
      const Complex kappa = std::cosh(k);
      const Vector vb{1.0, 0.0};
      const Perseverant pe(kappa * vb + Complex{0.3, 0.1}, vb, kappa * vb - Complex{0.3, 0.1});
      const auto series = pe.series_values(tau);
      const auto closed = pe.closed_form_values(tau);
      EXPECT_NEAR(std::abs(series.S - closed.S), 0.0, 1e-14) << dir << " " << tau;
      EXPECT_NEAR(std::abs(series.Q - closed.Q), 0.0, 1e-14) << dir << " " << tau;
      EXPECT_NEAR(std::abs(series.R - closed.R), 0.0, 1e-13) << dir << " " << tau;
    }
  }
}

TEST(Perseverant, LimitsAreTheParabolaAndTheCubic) {
  const Perseverant pe({-1.0, 0.0}, {1.0, 0.0}, {3.0, 0.0});  // kappa = 1 exactly
  for (double tau : {-2.0, -0.5, 0.0, 0.4, 1.0, 3.0}) {
    const auto v = pe.values(tau);
    EXPECT_NEAR(std::abs(v.S - tau), 0.0, 1e-15);
    EXPECT_NEAR(std::abs(v.Q - tau * tau), 0.0, 1e-14);
    EXPECT_NEAR(std::abs(v.R - tau * (tau * tau - 1.0) / 3.0), 0.0, 1e-14);
  }
}

TEST(Perseverant, RefusesTheSingularConfiguration) {
  // v_A + v_C = -2 v_B: cosh k = -1, no solution.
  EXPECT_THROW(Perseverant({-1.0, 0.0}, {1.0, 0.0}, {-1.0, 0.0}), MotionDomainError);
  EXPECT_THROW(Perseverant({-1.5, 0.0}, {1.0, 0.0}, {-0.5, 1e-12}), MotionDomainError);
  EXPECT_NO_THROW(Perseverant({-1.5, 0.0}, {1.0, 0.0}, {-0.5, 1e-3}));
}

}  // namespace
}  // namespace pita::test
