// The area of the moving shapes over time (src/analysis/area_time.cpp; SAM
// paper Sec. 6.3, Fig. 9): SAM's det L(t) = det(B) det(A)^t, monotonic;
// rARAP's computed directly from core's RarapMorph, not monotonic for the
// poses of scenes/sam-fig09-area.json.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "analysis/area_time.hpp"
#include "core/rarap_morph.hpp"
#include "motion/sampler.hpp"
#include "motion/scene_motion.hpp"
#include "scene/scene.hpp"

namespace pita::analysis {
namespace {

const char* const kPoses = R"("poses": [
    {"t": 0, "triangle": [[0, 0], [2, 0], [0.5, 1.6]]},
    {"t": 1, "triangle": [[5.6027, -1.272], [4.4402, 4.0462], [4.3668, 1.9044]]}])";

scene::Scene fig9(const std::string& method) {
  return scene::parse_scene("{\"method\": \"" + method + "\", " + kPoses + "}", "s.json");
}

// The pose mapping the reference triangle (0,0), (1,0), (0,1) onto a, b, c.
Affine2 pose(Eigen::Vector2d a, Eigen::Vector2d b, Eigen::Vector2d c) {
  Affine2 A;
  A.L.col(0) = b - a;
  A.L.col(1) = c - a;
  A.b = a;
  return A;
}
const Affine2 kB = pose({0, 0}, {2, 0}, {0.5, 1.6});
const Affine2 kC = pose({5.6027, -1.272}, {4.4402, 4.0462}, {4.3668, 1.9044});

TEST(AreaTime, SamAreaIsTheClosedFormAndMonotone) {
  const motion::SceneMotion motion = motion::build_motion(fig9("SAM"));
  const std::vector<double> times = motion::uniform_times(0.0, 1.0, 101);
  const AreaCurve curve = area_over_time(motion, times);
  const double det_b = kB.L.determinant(), ratio = kC.L.determinant() / det_b;  // det(A) = det C / det B
  ASSERT_EQ(curve.areas.size(), times.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_NEAR(curve.areas[i], det_b * std::pow(ratio, times[i]), 1e-12) << times[i];  // Sec. 6.3
  }
  EXPECT_NEAR(ratio, 0.9, 1e-3);  // the scene's design: det(A) = 0.9
  EXPECT_TRUE(curve.stats.monotone);
  EXPECT_NEAR(curve.largest, det_b, 1e-12);
  EXPECT_NEAR(curve.smallest, det_b * ratio, 1e-12);
}

TEST(AreaTime, RarapAreaRisesThenFalls) {
  const motion::SceneMotion motion = motion::build_motion(fig9("rARAP"));
  const std::vector<double> times = motion::uniform_times(0.0, 1.0, 1001);
  const AreaCurve curve = area_over_time(motion, times);
  // Directly from core's morph, about the reference triangle's barycentre.
  const RarapMorph rarap(kB, kC, Eigen::Vector2d(1.0 / 3.0, 1.0 / 3.0));
  double largest = 0.0, t_of_largest = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double det = rarap.at(times[i]).L.determinant();
    EXPECT_NEAR(curve.areas[i], det, 1e-12) << times[i];
    // The design: ARAP's stretch (1 - u) I + u S with S's eigenvalues 3 and
    // 0.3 has det (1 + 2 u)(1 - 0.7 u) (the poses are rounded to 1e-4).
    const double u = times[i];
    EXPECT_NEAR(det / kB.L.determinant(), (1.0 + 2.0 * u) * (1.0 - 0.7 * u), 1e-3) << u;
    if (det > largest) {
      largest = det;
      t_of_largest = u;
    }
  }
  EXPECT_FALSE(curve.stats.monotone);
  EXPECT_GT(largest, curve.areas.front() * 1.25);  // rises by more than 25 %
  EXPECT_GT(largest, curve.areas.back());
  EXPECT_NEAR(t_of_largest, 1.3 / 2.8, 2e-3);  // d/du (1 + 2u)(1 - 0.7u) = 0
  EXPECT_NEAR(curve.t_of_largest, t_of_largest, 1e-12);
  EXPECT_NEAR(curve.largest, largest, 1e-12);
  // area_stats (as `pita measure`): the dip against the falling trend is
  // measured from the peak, (largest - start) relative to the largest |det|.
  EXPECT_NEAR(curve.stats.excursion, (largest - curve.areas.front()) / largest, 1e-12);
}

}  // namespace
}  // namespace pita::analysis
