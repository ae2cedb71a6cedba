// Scene parsing (src/scene/scene.cpp): the parts of SceneError, method
// overrides, files. Arrow scenes are read by arrow_scene_reader.cpp
// (test_arrow_scene_reader.cpp), pose scenes by pose_scene_reader.cpp, panels
// by panel_reader.cpp, the text by json_text.cpp. Keyframes are read by
// json_reader.cpp (test_json_reader.cpp), poses by pose_reader.cpp
// (test_pose_reader.cpp). The bad scenes are files of tests/data/bad/,
// run by test_bad_scenes.cpp. Every error test asserts the whole message: file,
// JSON Pointer and reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "scene/scene.hpp"
#include "scene_test_support.hpp"
#include "support/keys.hpp"

namespace pita::scene {
namespace {

using test::p6_with;
using test::p6_with_middle;

// ------------------------------------------------------------ good scenes

TEST(SceneError, ErrorCarriesItsParts) {
  try {
    parse_scene("{\n\n  ]", "s.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.file(), "s.json");
    EXPECT_EQ(error.line(), 3);
    EXPECT_EQ(error.column(), 3);
    EXPECT_EQ(error.pointer(), "");
  }
  try {
    parse_scene(p6_with_middle(R"({"t": 0.5, "p": [1, 0], "m": -2, "w": 1})"), "s.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.pointer(), "/keyframes/1/m");
    EXPECT_EQ(error.reason(), "magnitude must be > 0 (got -2)");
    EXPECT_EQ(error.line(), 0);
  }
}

// ------------------------------------------------------------ methods and files

TEST(Scene, ResolveMethod) {
  EXPECT_EQ(resolve_method("P8"), Method::P8);
  EXPECT_EQ(resolve_method("lo-pe"), Method::P8);
  try {
    resolve_method("P66");
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()).rfind("unknown method \"P66\"; did you mean P6 (La-LP)", 0), 0u)
        << error.what();
  }
}

TEST(Scene, WithMethodReplacesTheMethodWhenTheCountFits) {
  const Scene scene = with_method(parse_scene(p6_with(""), "s.json"), Method::P8);
  EXPECT_EQ(track_keys(scene).method, Method::P8);
  EXPECT_EQ(method_id(scene.keys), "P8");
  try {
    with_method(parse_scene(p6_with(R"(, "chain": "blend")"), "s.json"), Method::SMA);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("s.json: /chain: chain \"blend\" blends a method through three"),
              std::string::npos)
        << error.what();
  }
}

TEST(Scene, LoadSceneReportsUnreadableFiles) {
  try {
    load_scene("no/such/scene.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_STREQ(error.what(),
                 "no/such/scene.json: cannot open the scene file (No such file or directory)");
  }
  try {
    load_scene(std::filesystem::temp_directory_path());
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.reason(), "cannot read the scene file: it is a directory");
  }
}

TEST(Scene, LoadSceneNamesTheFileAsGiven) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("pita-test-scene-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({"method": "P6", "keyframes": []})";
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() + ": /keyframes: method P6 (La-LP) takes at least 3 keyframes (got 0); more are chained "
                              "(\"chain\")");
  }
  std::filesystem::remove(path);
}

// ------------------------------------------------------------ pose scenes
//
// What the scene makes of its pose panels and method overrides; reading the
// poses themselves is test_pose_reader.cpp.

TEST(PoseScene, MethodOverride) {
  const Scene scene = parse_scene(R"({"method": "SAM", "poses": [
      {"t": 0, "matrix": [[1, 0, 0], [0, 1, 0]]}, {"t": 1, "matrix": [[0, -1, 2], [1, 0, 2]]}]})",
                                  "s.json");
  EXPECT_EQ(method_id(with_method(scene, PoseMethod::linear).keys), "linear");
  EXPECT_THROW(with_method(scene, PoseMethod::biarc_sam), SceneError);  // 3 poses
  EXPECT_THROW(with_method(scene, Method::P6), SceneError);
}

}  // namespace
}  // namespace pita::scene
