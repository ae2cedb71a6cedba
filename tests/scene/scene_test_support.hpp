// Helpers shared by the scene tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

namespace pita::scene::test {

// The source tree (schema/, scenes/) and a JSON file of it, parsed.
inline const std::filesystem::path kSourceDir = PITA_SOURCE_DIR;
inline nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot open " << path;
  return nlohmann::json::parse(in);
}

// The reader the readers' tests hand values to: errors name "s.json".
inline const detail::JsonReader kReader("s.json");

// The three keyframes of a valid P6 scene, as the member "keyframes": [...].
inline const std::string kKeyframes = R"("keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}])";

// A P6 scene whose middle keyframe is `middle` (JSON text).
inline std::string p6_with_middle(const std::string& middle) {
  return R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0}, )" + middle +
         R"(, {"t": 1, "p": [2, 0], "m": 1, "w": 0}]})";
}

// A valid P6 scene with `extra` members added at the top level (",\"samples\": 3").
inline std::string p6_with(const std::string& extra) {
  return R"({"method": "P6", "keyframes": [{"t": 0, "p": [0, 0], "m": 1, "w": 0},
    {"t": 0.5, "p": [1, 1], "m": 1, "w": 0}, {"t": 1, "p": [2, 0], "m": 1, "w": 0}])" +
         extra + "}";
}

// Every field of a line style as expected.
inline void expect_same_line(const LineStyle& actual, const LineStyle& expected) {
  EXPECT_EQ(actual.color, expected.color);
  EXPECT_EQ(actual.width, expected.width);
  EXPECT_EQ(actual.opacity, expected.opacity);
  EXPECT_EQ(actual.dash, expected.dash);
}

// The message of the SceneError that parsing `text` (as "s.json") throws, or "(no error)".
inline std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

// "pointer: reason" of the SceneError that `read` throws, or "(no error)";
// the error must name `file` (kReader's by default).
template <typename Read>
std::string failure(Read&& read, const std::string& file = "s.json") {
  try {
    read();
  } catch (const SceneError& error) {
    EXPECT_EQ(error.file(), file);
    return error.pointer() + ": " + error.reason();
  }
  return "(no error)";
}

// The single layer of a P6 scene whose "layers" is [`layer`] (JSON text), as a T.
template <typename T>
T only_layer(const std::string& layer) {
  const Scene scene = parse_scene(p6_with(R"(, "layers": [)" + layer + "]"), "s.json");
  EXPECT_EQ(figure_of<KeyframeKeys>(scene).layers.size(), 1U);
  EXPECT_TRUE(std::holds_alternative<T>(figure_of<KeyframeKeys>(scene).layers.at(0)));
  return std::get<T>(figure_of<KeyframeKeys>(scene).layers.at(0));
}

}  // namespace pita::scene::test
