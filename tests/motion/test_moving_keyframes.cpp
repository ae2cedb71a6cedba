// Moving keyframes (src/motion/moving_keyframes.cpp, PITA Sec. 7.4).
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "core/steady_morph.hpp"
#include "motion/moving_keyframes.hpp"
#include "motion/scene_motion.hpp"
#include "scene/scene.hpp"
#include "support/keys.hpp"

namespace pita::motion {
namespace {

constexpr const char* kMoving = R"({"method": "P6", "keyframes": [
  {"t": 0, "from": {"p": [0, 0], "m": 1, "w": 0.5}, "to": {"p": [0, -3], "m": 2, "w": 1.5}},
  {"t": 1, "p": [3, 1], "m": 0.8, "w": 1.2},
  {"t": 2, "from": {"p": [6, 0], "m": 1, "w": 2}, "to": {"p": [6.5, -4], "m": 0.5, "w": -1}}],
  "panels": [{"title": "scene's"}, {"method": "P8", "keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 1], "m": 1, "w": 0},
    {"t": 2, "from": {"p": [2, 0], "m": 1, "w": 0}, "to": {"p": [2, 2], "m": 1, "w": 3.14159}}]}]})";

double frame_distance(const Arrow& a, const Arrow& b) {
  return std::max({std::abs(a.p - b.p), std::abs(a.q() - b.q()), std::abs(a.w - b.w)});
}

TEST(MovingKeyframes, ReadAsFromAndTo) {
  const scene::Scene scene = scene::parse_scene(kMoving, "moving.json");
  ASSERT_EQ(arrow_keys(scene).keyframes_to.size(), 3u);
  EXPECT_EQ(arrow_keys(scene).keyframes[0].arrow.p, Point(0, 0));
  EXPECT_EQ(arrow_keys(scene).keyframes_to[0].p, Point(0, -3));
  // a keyframe that does not move is its own target
  EXPECT_EQ(frame_distance(arrow_keys(scene).keyframes_to[1], arrow_keys(scene).keyframes[1].arrow), 0.0);
  EXPECT_TRUE(has_moving_keyframes(scene));
  EXPECT_FALSE(has_moving_keyframes(scene::parse_scene(
      R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 1, "p": [1, 0], "m": 1, "w": 0},
          {"t": 2, "p": [2, 0], "m": 1, "w": 0}]})",
      "still.json")));
}

TEST(MovingKeyframes, TauZeroAndOneAreFromAndTo) {
  const scene::Scene scene = scene::parse_scene(kMoving, "moving.json");
  const scene::Scene start = scene_at(scene, 0.0), end = scene_at(scene, 1.0);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_LT(frame_distance(arrow_keys(start).keyframes[i].arrow, arrow_keys(scene).keyframes[i].arrow), 1e-12) << i;
    EXPECT_LT(frame_distance(arrow_keys(end).keyframes[i].arrow, arrow_keys(scene).keyframes_to[i]), 1e-12) << i;
    EXPECT_EQ(arrow_keys(start).keyframes[i].t, arrow_keys(scene).keyframes[i].t);
  }
  EXPECT_TRUE(arrow_keys(start).keyframes_to.empty());
  EXPECT_FALSE(has_moving_keyframes(start));
}

TEST(MovingKeyframes, EachMovesByItsSteadyMorph) {
  // Independently: SMA(A, B, s) = A.p + (e^{sL} - 1)/(e^L - 1) (B.p - A.p) on p,
  // with L = ln(mB/mA) + i(wB - wA) (PITA Eq. 19-20), and m, w interpolated
  // geometrically and linearly.
  const scene::Scene scene = scene::parse_scene(kMoving, "moving.json");
  const Arrow A = arrow_keys(scene).keyframes[2].arrow, B = arrow_keys(scene).keyframes_to[2];
  for (const double tau : {0.25, 0.5, 0.8, 1.3}) {
    const Arrow moved = arrow_keys(scene_at(scene, tau)).keyframes[2].arrow;
    const std::complex<double> L(std::log(B.m / A.m), B.w - A.w);
    const Point p = A.p + (std::exp(tau * L) - 1.0) / (std::exp(L) - 1.0) * (B.p - A.p);
    EXPECT_LT(std::abs(moved.p - p), 1e-12) << tau;
    EXPECT_NEAR(moved.m, A.m * std::pow(B.m / A.m, tau), 1e-12);
    EXPECT_NEAR(moved.w, A.w + tau * (B.w - A.w), 1e-12);
  }
}

TEST(MovingKeyframes, PanelsMoveTheirOwnKeyframes) {
  const scene::Scene scene = scene::parse_scene(kMoving, "moving.json");
  const scene::Scene half = scene_at(scene, 0.5);
  ASSERT_EQ(half.panels.size(), 2u);
  EXPECT_LT(frame_distance(arrow_keys(half.panels[0]).keyframes[0].arrow, arrow_keys(half).keyframes[0].arrow), 1e-15);
  EXPECT_LT(frame_distance(arrow_keys(half.panels[1]).keyframes[2].arrow,
                           steady_morph(arrow_keys(scene.panels[1]).keyframes[2].arrow,
                                        arrow_keys(scene.panels[1]).keyframes_to[2], 0.5)),
            1e-15);
  // The pattern at tau goes through the keyframes at tau.
  const SceneMotion motion = build_motion(half, half.panels[1]);
  EXPECT_LT(frame_distance(motion.arrow_at(2.0), arrow_keys(half.panels[1]).keyframes[2].arrow), 1e-9);
}

}  // namespace
}  // namespace pita::motion
