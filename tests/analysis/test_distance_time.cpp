// The distance-time function (src/analysis/distance_time.cpp): the diagonal
// for constant speed, the ease itself under arc length, the knots' share of
// the path otherwise.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "analysis/distance_time.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {
namespace {

scene::Scene p6(const std::string& timing) {
  return scene::parse_scene(R"({"method": "P6", "keyframes": [
      {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2},
      {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])" +
                                timing + "}",
                            "s.json");
}

TEST(DistanceTime, ArcLengthWithLinearEaseIsTheDiagonal) {
  const motion::SceneMotion m = motion::build_motion(p6(R"(, "timing": {"arc_length": "p"})"));
  const std::vector<double> times = motion::uniform_times(0.0, 1.0, 21);
  for (const Point xy : distance_time(m, scene::TrackedPoint::start, times)) EXPECT_NEAR(xy.imag(), xy.real(), 1e-10);
}

TEST(DistanceTime, ArcLengthWithAnEaseIsTheEase) {
  const motion::SceneMotion m =
      motion::build_motion(p6(R"(, "timing": {"ease": {"parabolic": {"t1": 0.3, "t2": 0.6}}, "arc_length": "q"})"));
  const Ease e = parabolic_ease(0.3, 0.6);
  const std::vector<double> times = motion::uniform_times(0.0, 1.0, 21);
  for (const Point xy : distance_time(m, scene::TrackedPoint::end, times)) {
    EXPECT_NEAR(xy.imag(), ease(e, xy.real()), 1e-10) << xy.real();
  }
}

TEST(DistanceTime, UnwarpedMotionEndsAtOneAndIncreases) {
  const motion::SceneMotion m = motion::build_motion(p6(""));
  const std::vector<double> times = motion::uniform_times(0.0, 1.0, 101);
  const std::vector<Point> curve = distance_time(m, scene::TrackedPoint::middle, times);
  EXPECT_EQ(curve.front(), Point(0.0, 0.0));
  EXPECT_NEAR(curve.back().imag(), 1.0, 1e-15);
  for (std::size_t i = 1; i < curve.size(); ++i) EXPECT_GE(curve[i].imag(), curve[i - 1].imag());
  // Not the diagonal: P6's point does not move at constant speed.
  double worst = 0.0;
  for (const Point xy : curve) worst = std::max(worst, std::abs(xy.imag() - xy.real()));
  EXPECT_GT(worst, 1e-2);
}

}  // namespace
}  // namespace pita::analysis
