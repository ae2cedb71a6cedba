// Frame predictions and their discrepancy (src/analysis/prediction.cpp, the
// PITA paper's Sec. 6.1-6.2): each predictor's neighbours, and the zeros the
// paper implies on steady motions.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/prediction.hpp"
#include "core/discrepancy.hpp"
#include "core/keyframe.hpp"
#include "core/steady_morph.hpp"

namespace pita::analysis {
namespace {

// Frames of the steady morph from A to C at times 0, 0.1, ..., 1.
struct SteadySamples {
  std::vector<double> times;
  std::vector<Arrow> frames;
};
SteadySamples steady_samples() {
  const Arrow A{{0.0, 0.0}, 1.0, 0.3}, C{{4.0, 1.0}, 2.0, 2.5};
  SteadySamples s;
  for (int i = 0; i <= 10; ++i) {
    s.times.push_back(i / 10.0);
    s.frames.push_back(steady_morph(A, C, i / 10.0));
  }
  return s;
}

TEST(Prediction, PreviousIsTheFrameBefore) {
  const SteadySamples s = steady_samples();
  EXPECT_FALSE(predict_frame(Predictor::previous, Method::P6, {}, s.times, s.frames, 0).has_value());
  const std::optional<Arrow> p = predict_frame(Predictor::previous, Method::P6, {}, s.times, s.frames, 4);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->p, s.frames[3].p);
  EXPECT_EQ(p->w, s.frames[3].w);
  EXPECT_NEAR(*frame_discrepancy(Predictor::previous, Method::P6, {}, s.times, s.frames, 4),
              discrepancy(s.frames[4], s.frames[3]), 1e-15);
}

TEST(Prediction, SteadyAverageHasNoDiscrepancyOnASteadyMotion) {
  const SteadySamples s = steady_samples();
  EXPECT_FALSE(frame_discrepancy(Predictor::average, Method::P6, {}, s.times, s.frames, 0).has_value());
  EXPECT_FALSE(frame_discrepancy(Predictor::average, Method::P6, {}, s.times, s.frames, 10).has_value());
  for (std::size_t i = 1; i < 10; ++i) {
    EXPECT_NEAR(*frame_discrepancy(Predictor::average, Method::P6, {}, s.times, s.frames, i), 0.0, 1e-12) << i;
  }
}

TEST(Prediction, PitaThroughThreeSteadyFramesContinuesTheSteadyMotion) {
  // Fig. 28 / Sec. 7.5: with B = M(A, C) and even knots, P6 reproduces the
  // steady morph, so predicting the next frame from three is exact.
  const SteadySamples s = steady_samples();
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_FALSE(predict_frame(Predictor::pita, Method::P6, {}, s.times, s.frames, i).has_value());
  }
  for (std::size_t i = 3; i <= 10; ++i) {
    EXPECT_NEAR(*frame_discrepancy(Predictor::pita, Method::P6, {}, s.times, s.frames, i), 0.0, 1e-10) << i;
  }
  // SMA predicts from two frames.
  EXPECT_FALSE(predict_frame(Predictor::pita, Method::SMA, {}, s.times, s.frames, 1).has_value());
  EXPECT_NEAR(*frame_discrepancy(Predictor::pita, Method::SMA, {}, s.times, s.frames, 2), 0.0, 1e-10);
}

TEST(Prediction, PreviousFrameDiscrepancyIsPositiveOnAMovingMotion) {
  const SteadySamples s = steady_samples();
  for (std::size_t i = 1; i <= 10; ++i) {
    EXPECT_GT(*frame_discrepancy(Predictor::previous, Method::P6, {}, s.times, s.frames, i), 1e-3) << i;
  }
}

}  // namespace
}  // namespace pita::analysis
