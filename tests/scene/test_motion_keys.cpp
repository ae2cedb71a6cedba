// What a panel's motion is made of (src/scene/motion_keys.cpp): one
// alternative per kind, which parse_scene chooses from the scene's fields, and
// the few facts every kind answers (its method id, its JSON field, whether it
// has a motion to build).
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "scene/motion_keys.hpp"
#include "scene/scene.hpp"

namespace pita::scene {
namespace {

constexpr const char* kPosePair = R"("poses": [{"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]},
                                                {"t": 1, "matrix": [[2, 0, 1], [0, 2, 0]]}])";

TEST(MotionKeys, TheSceneFieldsChooseTheAlternative) {
  const Scene arrows = parse_scene(R"({"method": "SMA", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
      {"t": 1, "p": [1, 0], "m": 2, "w": 1}]})",
                                   "k.json");
  EXPECT_TRUE(std::holds_alternative<KeyframeKeys>(arrows.keys));
  const Scene points = parse_scene(R"({"method": "P6", "points": [{"t": 0, "p": [0, 0]}, {"t": 1, "p": [1, 0]},
      {"t": 2, "p": [1, 1]}, {"t": 3, "p": [0, 1]}]})",
                                   "p.json");
  ASSERT_TRUE(std::holds_alternative<PointKeys>(points.keys));
  EXPECT_EQ(std::get<PointKeys>(points.keys).points.size(), 4U);
  const Scene plane = parse_scene(std::string(R"({"method": "SAM", )") + kPosePair + "}", "a.json");
  ASSERT_TRUE(std::holds_alternative<PlanePoseKeys>(plane.keys));
  EXPECT_EQ(std::get<PlanePoseKeys>(plane.keys).poses.size(), 2U);
  const Scene space = parse_scene(R"({"method": "SAM", "dimension": 3, "poses": [
      {"t": 0, "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]},
      {"t": 1, "matrix": [[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0]]}]})",
                                  "s.json");
  ASSERT_TRUE(std::holds_alternative<SpacePoseKeys>(space.keys));
  EXPECT_EQ(std::get<SpacePoseKeys>(space.keys).poses[1].pose.b.x(), 1.0);
  // Every panel of a scene without "panels" is the scene itself, of its kind.
  EXPECT_EQ(space.panels.front().keys.index(), space.keys.index());
}

TEST(MotionKeys, MethodIdFieldAndWhetherThereIsAMotion) {
  KeyframeKeys arrows;
  arrows.method = Method::P2;
  arrows.keyframes = {Keyframe{0.0, Arrow{}}, Keyframe{1.0, Arrow{}}};
  PointKeys points;
  PlanePoseKeys plane;
  plane.method = PoseMethod::four_point;
  SpacePoseKeys space;
  EXPECT_EQ(method_id(MotionKeys(arrows)), "P2");
  EXPECT_EQ(method_id(MotionKeys(points)), "P6");
  EXPECT_EQ(method_id(MotionKeys(space)), "SAM");
  EXPECT_STREQ(keys_field(MotionKeys(arrows)), "/keyframes");
  EXPECT_STREQ(keys_field(MotionKeys(points)), "/points");
  EXPECT_STREQ(keys_field(MotionKeys(plane)), "/poses");
  EXPECT_STREQ(keys_field(MotionKeys(space)), "/poses");
  EXPECT_TRUE(has_motion_keys(MotionKeys(arrows)));
  EXPECT_FALSE(has_motion_keys(MotionKeys(plane)));  // a figure without poses
  plane.poses.push_back({0.0, Affine2::identity()});
  EXPECT_TRUE(has_motion_keys(MotionKeys(plane)));
  EXPECT_FALSE(has_motion_keys(MotionKeys(space)));
}

TEST(MotionKeys, TrackMethodOnlyForArrowsAndPoints) {
  MotionKeys keys = KeyframeKeys{};
  ASSERT_NE(track_method(keys), nullptr);
  track_method(keys)->method = Method::P4;
  EXPECT_EQ(std::get<KeyframeKeys>(keys).method, Method::P4);
  keys = PointKeys{};
  EXPECT_NE(track_method(keys), nullptr);
  keys = PlanePoseKeys{};
  EXPECT_EQ(track_method(keys), nullptr);
  const MotionKeys space = SpacePoseKeys{};
  EXPECT_EQ(track_method(space), nullptr);
}

TEST(MotionKeys, HandleIsTheFirstKeyframeUnlessGiven) {
  KeyframeKeys arrows;
  arrows.keyframes = {Keyframe{0.0, Arrow{Point{3.0, 4.0}, 2.0, 0.0}}, Keyframe{1.0, Arrow{}}};
  EXPECT_EQ(arrows.handle().p, Point(3.0, 4.0));
  EXPECT_EQ(arrows.handle().m, 2.0);
  arrows.given_handle = Arrow{Point{-1.0, 0.0}, 0.5, 0.0};
  EXPECT_EQ(arrows.handle().p, Point(-1.0, 0.0));
  EXPECT_EQ(arrows.track_length(), 2U);
  PointKeys points;
  points.points.resize(5);
  EXPECT_EQ(points.track_length(), 4U);  // n points chain n - 1 edge arrows
}

}  // namespace
}  // namespace pita::scene
