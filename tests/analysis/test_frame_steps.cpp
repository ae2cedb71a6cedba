// analysis/frame_steps.cpp against closed forms: the steady morph of two
// arrows (m(t) = m_0 (m_1/m_0)^t, w(t) linear: equal steps) and P1 through
// a flipped middle keyframe (Lagrange weights by hand), and P2's quadratic
// winding (the time of its largest turn step).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "analysis/frame_steps.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {
namespace {

TEST(FrameSteps, SteadyMorphStepsAreEqual) {
  // SMA from (m, w) = (1, 0) to (2, 1.2): m(t) = 2^t, w(t) = 1.2 t; 5 frames
  // at t = 0, 1/4, ..., 1 step by ln 2 / 4 in log-magnitude and 0.3 rad.
  const scene::Scene scene = scene::parse_scene(R"({"method": "SMA", "samples": 5, "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [3, 1], "m": 2, "w": 1.2}]})",
                                                "test.json");
  const FrameSteps steps = frame_steps(motion::Stage(scene), 0);
  EXPECT_NEAR(steps.scale_step, std::log(2.0) / 4.0, 1e-12);
  EXPECT_NEAR(steps.turn_step, 0.3, 1e-12);
  EXPECT_NEAR(steps.scale_min, 1.0, 1e-12);  // never below the smaller keyframe
  EXPECT_NEAR(steps.scale_max, 1.0, 1e-12);  // nor above the larger
}

TEST(FrameSteps, ShrinkingAndFlipsOfP1) {
  // P1 blends the vectors (0, 2), (0, -2), (0, 2) at knots 0, 1/2, 1 by the
  // Lagrange weights: v(t) = 2 (1 - 8 t (1 - t)) i, which is 2 i at the
  // ends, 0 at t = (1 -+ 1/sqrt 2)/2 and -2 i at t = 1/2. Frames at t = 0,
  // 1/4, 1/2, 3/4, 1: v = 2i, -i, -2i, -i, 2i, so the direction flips
  // (pi) between the first two frames and the magnitude halves (ln 2).
  const scene::Scene scene = scene::parse_scene(R"({"method": "P1", "samples": 5, "keyframes": [
      {"t": 0, "p": [0, 0], "q": [0, 2]}, {"t": 0.5, "p": [1, 0], "q": [1, -2]},
      {"t": 1, "p": [2, 0], "q": [2, 2]}]})",
                                                "test.json");
  const FrameSteps steps = frame_steps(motion::Stage(scene), 0);
  EXPECT_NEAR(steps.scale_step, std::log(2.0), 1e-12);
  EXPECT_NEAR(steps.turn_step, std::numbers::pi, 1e-12);
  EXPECT_NEAR(steps.scale_min, 0.0, 1e-2);  // dense samples pass near the zeros
  EXPECT_NEAR(steps.scale_max, 1.0, 1e-12);
}

TEST(FrameSteps, P2TurnsFastestInItsLastStep) {
  // P2 blends the windings 0, 1, 3 at knots 0, 1, 2 with the Lagrange
  // weights (PITA Eq. 10): w(t) = (t^2 + t) / 2, so the five frames at t = 0, 1/2,
  // 1, 3/2, 2 have w = 0, 3/8, 1, 15/8, 3; the steps 3/8, 5/8, 7/8, 9/8 grow,
  // the largest is the last, half-way through it t = 7/4 (Fig. 24's P2).
  const scene::Scene scene = scene::parse_scene(R"({"method": "P2", "samples": 5, "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [2, 1], "m": 1, "w": 1},
      {"t": 2, "p": [4, 0], "m": 1, "w": 3}]})",
                                                "test.json");
  const FrameSteps steps = frame_steps(motion::Stage(scene), 0);
  EXPECT_NEAR(steps.turn_step, 9.0 / 8.0, 1e-12);
  EXPECT_DOUBLE_EQ(steps.turn_step_time, 1.75);
  EXPECT_EQ(frame_step(steps, scene::MeasureKind::turn_step_time), steps.turn_step_time);
}

TEST(FrameSteps, EqualStepsGiveTheTimeOfOneOfThem) {
  // The steady morph's steps are equal (0.3 rad each, up to rounding): the
  // time is that of a step, half-way between two of the frames' times.
  const scene::Scene scene = scene::parse_scene(R"({"method": "SMA", "samples": 5, "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [3, 1], "m": 2, "w": 1.2}]})",
                                                "test.json");
  const double t = frame_steps(motion::Stage(scene), 0).turn_step_time;
  EXPECT_TRUE(t == 0.125 || t == 0.375 || t == 0.625 || t == 0.875) << t;
}

}  // namespace
}  // namespace pita::analysis
