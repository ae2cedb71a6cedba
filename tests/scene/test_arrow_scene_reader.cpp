// Arrow scenes (src/scene/arrow_scene_reader.cpp): keyframes in both forms,
// defaults, samples, options, method names. Refusals: tests/data/bad/.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::p6_with;
using test::p6_with_middle;

TEST(Scene, ReadsMagnitudeWindingForm) {
  const Scene scene = parse_scene(R"({
    "$schema": "../schema/scene.schema.json",
    "description": "three arrows",
    "method": "P6",
    "keyframes": [
      {"t": 0,   "p": [0, 0],   "m": 1,   "w": 0.4},
      {"t": 0.5, "p": [3, 1.5], "m": 0.6, "w": 2.0},
      {"t": 1,   "p": [6, 0],   "m": 1.2, "w": -3.5}
    ]
  })",
                                  "s.json");
  EXPECT_EQ(scene.path, "s.json");
  EXPECT_EQ(scene.description, "three arrows");
  EXPECT_EQ(scene.method_name, "P6");
  EXPECT_EQ(scene.method, Method::P6);
  EXPECT_FALSE(scene.samples.has_value());
  ASSERT_EQ(scene.keyframes.size(), 3u);
  EXPECT_EQ(scene.keyframes[1].t, 0.5);
  EXPECT_EQ(scene.keyframes[1].arrow.p, make_point(3, 1.5));
  EXPECT_EQ(scene.keyframes[1].arrow.m, 0.6);
  EXPECT_EQ(scene.keyframes[1].arrow.w, 2.0);
  EXPECT_EQ(scene.keyframes[2].arrow.w, -3.5);  // windings are never reduced
}

TEST(Scene, DefaultsApplied) {
  const Scene scene = parse_scene(p6_with(""), "s.json");
  EXPECT_EQ(scene.description, "");
  EXPECT_FALSE(scene.samples.has_value());
  EXPECT_EQ(scene.options.anchor, Anchor::start);
  EXPECT_EQ(scene.options.path_mean, MeanKind::geometric);
  EXPECT_EQ(scene.options.magnitude_mean, MeanKind::geometric);
}

TEST(Scene, ReadsSamplesAndOptions) {
  const Scene scene = parse_scene(
      p6_with(R"(, "samples": 1000000, "options": {"anchor": "midpoint", "path_mean": "arithmetic",
                  "magnitude_mean": "harmonic"})"),
      "s.json");
  EXPECT_EQ(scene.samples, 1000000);
  EXPECT_EQ(scene.options.anchor, Anchor::midpoint);
  EXPECT_EQ(scene.options.path_mean, MeanKind::arithmetic);
  EXPECT_EQ(scene.options.magnitude_mean, MeanKind::harmonic);
  EXPECT_EQ(parse_scene(p6_with(R"(, "samples": 2)"), "s.json").samples, 2);
}

TEST(Scene, MethodNamesAreResolvedToCanonicalIds) {
  const std::string keyframes =
      R"("keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, {"t": 0.5, "p": [1, 1], "m": 1, "w": 0},
                       {"t": 1, "p": [2, 0], "m": 1, "w": 0}]})";
  const Scene mnemonic = parse_scene(R"({"method": "la-lp", )" + keyframes, "s.json");
  EXPECT_EQ(mnemonic.method, Method::P6);
  EXPECT_EQ(mnemonic.method_name, "P6");
  const Scene number = parse_scene(R"({"method": "5s", )" + keyframes, "s.json");
  EXPECT_EQ(number.method_name, "P5S");
}

TEST(Scene, SmaTakesTwoKeyframes) {
  const Scene scene = parse_scene(R"({"method": "SMA", "keyframes": [
    {"t": 0, "p": [0, 0], "m": 2, "w": 0.3}, {"t": 1, "p": [4, 1], "m": 0.5, "w": 4.3}]})",
                                  "s.json");
  EXPECT_EQ(scene.method, Method::SMA);
  EXPECT_EQ(scene.keyframes.size(), 2u);
}

// ------------------------------------------------------------ bad scenes
//
// Every bad scene is a file of tests/data/bad/ with the pointer (or line and
// column) and the reason it must give: tests/scene/test_bad_scenes.cpp runs
// them. Here: the parts of SceneError, and the limits' good side.

}  // namespace
}  // namespace pita::scene
