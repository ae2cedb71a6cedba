// Titles that name fields of their scene (src/scene/title_template.cpp).
#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::p6_with;

TEST(TitleTemplate, ShowsTheValuesAtItsPointers) {
  const Scene scene = parse_scene(p6_with(R"(, "title": "{/method}: B at t = {/keyframes/1/t}, {/keyframes/1/p/0} {x}",
                "panels": [{"method": "P2", "title": "{/panels/0/method} beside {/method}"}])"),
                                  "s.json");
  EXPECT_EQ(scene.title, "P6: B at t = 0.5, 1 {x}");
  EXPECT_EQ(scene.panels.at(0).title, "P2 beside P6");
  // No template: the text as it is, braces included.
  EXPECT_EQ(parse_scene(p6_with(R"(, "title": "{a} and {/ b")"), "s.json").title, "{a} and {/ b");
}

TEST(TitleTemplate, APointerToNothingOrToAnObjectIsRefused) {
  try {
    (void)parse_scene(p6_with(R"(, "title": "by {/methd}")"), "s.json");
    FAIL() << "accepted";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/title");
    EXPECT_NE(error.reason().find("\"{/methd}\" names no field of the scene"), std::string::npos) << error.reason();
  }
  try {
    (void)parse_scene(p6_with(R"(, "panels": [{"title": "{/keyframes/0}"}])"), "s.json");
    FAIL() << "accepted";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/panels/0/title");
    EXPECT_NE(error.reason().find("names an object"), std::string::npos) << error.reason();
  }
}

}  // namespace
}  // namespace pita::scene
