// What `pita eval` and Python's Scene.eval evaluate (src/motion/evaluation.cpp):
// the scene's own motion, which is not the first panel's when the panels
// change the method, or a panel's; a panel the scene does not have is refused
// with the count; a panel whose motion does not exist fails the whole scene.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "motion/evaluation.hpp"
#include "motion/no_motion.hpp"
#include "scene/scene.hpp"

namespace pita::motion {
namespace {

const std::string kEvaluationKeyframes = R"("keyframes": [
    {"t": 0, "p": [0, 0], "m": 1, "w": 0.4}, {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2},
    {"t": 1, "p": [6, 0], "m": 1.2, "w": 3.5}])";

TEST(Evaluation, TheScenesOwnMotionWhenItIsNotTheFirstPanels) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", )" + kEvaluationKeyframes + R"(, "panels": [{"method": "P1"}, {"method": "P8"}]})", "e.json");
  const Evaluation own(scene, std::nullopt);
  EXPECT_EQ(own.motion().method_id(), "P6");
  const Evaluation second(scene, 1);
  EXPECT_EQ(second.motion().method_id(), "P8");
  EXPECT_EQ(second.panel().pointer, "/panels/1");
}

TEST(Evaluation, WithoutPanelsTheOwnMotionIsTheStagesFirst) {
  const scene::Scene scene = scene::parse_scene(R"({"method": "P3", )" + kEvaluationKeyframes + "}", "e.json");
  const Evaluation own(scene, std::nullopt);
  EXPECT_EQ(own.motion().method_id(), "P3");
  const Evaluation first(scene, 0);
  EXPECT_EQ(first.motion().method_id(), "P3");
  const Arrow a = own.motion().arrow_at(0.3), b = first.motion().arrow_at(0.3);
  EXPECT_EQ(a.p, b.p);
  EXPECT_EQ(a.w, b.w);
}

TEST(Evaluation, APanelTheSceneDoesNotHaveIsRefusedWithTheCount) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "P6", )" + kEvaluationKeyframes + R"(, "panels": [{"method": "P1"}, {"method": "P8"}]})", "e.json");
  for (const int panel : {2, -1}) {
    try {
      const Evaluation evaluation(scene, panel);
      ADD_FAILURE() << "panel " << panel << " was accepted";
    } catch (const std::out_of_range& error) {
      EXPECT_EQ(std::string(error.what()), "e.json has 2 panels (0 to 1); got " + std::to_string(panel));
    }
  }
}

TEST(Evaluation, APanelWithoutAMotionFailsTheScene) {
  const scene::Scene scene = scene::parse_scene(
      R"({"method": "SAM", "poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[2, 0, 0], [0, 2, 0]]}],
          "panels": [{}, {"poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
                                    {"t": 1, "matrix": [[-1.5, 0, 0], [0, -0.6666, 0]]}]}]})",
      "p.json");
  EXPECT_THROW(Evaluation(scene, 0), NoMotion);
  EXPECT_THROW(Evaluation(scene, std::nullopt), NoMotion);
}

}  // namespace
}  // namespace pita::motion
