// The one writer of points and arrows as JSON (src/scene/arrow_json.cpp).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/arrow_json.hpp"

namespace pita::scene {
namespace {

TEST(ArrowJson, WritesAnArrowAsASceneGivesIt) {
  const Arrow a{Point{1.5, -2.0}, 0.25, 3.0};
  EXPECT_EQ(arrow_json(a).dump(), R"({"p":[1.5,-2.0],"m":0.25,"w":3.0})");
  EXPECT_EQ(point_json(Point{0.0, 1e-3}).dump(), "[0.0,0.001]");
}

TEST(ArrowJson, KeepsMembersAddedAroundIt) {
  nlohmann::ordered_json keyframe{{"t", 2.0}};
  keyframe.update(arrow_json(Arrow{Point{0.0, 0.0}, 1.0, 0.0}));
  EXPECT_EQ(keyframe.dump(), R"({"t":2.0,"p":[0.0,0.0],"m":1.0,"w":0.0})");
}

}  // namespace
}  // namespace pita::scene
