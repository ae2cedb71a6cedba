// "golden" (src/scene/golden_reader.cpp): a scene's own tolerances.
#include <string>

#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::p6_with;
using test::p6_with_middle;

TEST(GoldenReader, EveryToleranceIsReadAndTheRestStayUnset) {
  const Scene all = parse_scene(p6_with(R"(, "golden": {"number_tolerance": 1e-6, "svg_tolerance": 0.5,
      "pixel_tolerance": 20, "max_differing": 0.01})"),
                                "s.json");
  EXPECT_EQ(all.golden.numbers, 1e-6);
  EXPECT_EQ(all.golden.svg, 0.5);
  EXPECT_EQ(all.golden.pixel, 20);
  EXPECT_EQ(all.golden.max_differing, 0.01);
  const Scene some = parse_scene(p6_with(R"(, "golden": {"pixel_tolerance": 0})"), "s.json");
  EXPECT_EQ(some.golden.pixel, 0);
  EXPECT_FALSE(some.golden.numbers.has_value());
  EXPECT_FALSE(parse_scene(p6_with(""), "s.json").golden.svg.has_value());
}

TEST(GoldenReader, BoundsAreChecked) {
  const auto pointer = [](const std::string& golden) {
    try {
      parse_scene(p6_with(R"(, "golden": )" + golden), "s.json");
    } catch (const SceneError& error) {
      return error.pointer();
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(pointer(R"({"number_tolerance": 1.5})"), "/golden/number_tolerance");
  EXPECT_EQ(pointer(R"({"svg_tolerance": 1001})"), "/golden/svg_tolerance");
  EXPECT_EQ(pointer(R"({"pixel_tolerance": 256})"), "/golden/pixel_tolerance");
  EXPECT_EQ(pointer(R"({"pixel_tolerance": 2.5})"), "/golden/pixel_tolerance");
  EXPECT_EQ(pointer(R"({"max_differing": -0.1})"), "/golden/max_differing");
  EXPECT_EQ(pointer(R"({"pixels": 3})"), "/golden/pixels");
  EXPECT_EQ(pointer(R"({"svg_tolerance": 1000, "max_differing": 1})"), "(no error)");
}

}  // namespace
}  // namespace pita::scene
