// The files of the repository that the scene layer reads: the published
// schema (schema/scene.schema.json) and every starter scene (scenes/*.json).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/pitas/registry.hpp"
#include "scene/scene.hpp"

namespace pita::scene {
namespace {

const std::filesystem::path kSourceDir = PITA_SOURCE_DIR;

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot open " << path;
  return nlohmann::json::parse(in);
}

std::set<std::string> keys_of(const nlohmann::json& object) {
  std::set<std::string> keys;
  for (const auto& [key, value] : object.items()) keys.insert(key);
  return keys;
}

std::vector<std::filesystem::path> scene_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(kSourceDir / "scenes")) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(SceneSchema, IsValidJsonDraft202012) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  EXPECT_EQ(schema.at("$schema"), "https://json-schema.org/draft/2020-12/schema");
  EXPECT_EQ(schema.at("type"), "object");
  EXPECT_EQ(schema.at("additionalProperties"), false);
}

// The schema lists exactly the fields the parser accepts (tests/scene/test_scene.cpp
// checks that the parser refuses every other one).
TEST(SceneSchema, DescribesExactlyTheAcceptedFields) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  EXPECT_EQ(keys_of(schema.at("properties")),
            (std::set<std::string>{"$schema", "description", "method", "keyframes", "samples",
                                   "options"}));
  EXPECT_EQ(schema.at("required"), (nlohmann::json{"method", "keyframes"}));
  const nlohmann::json& keyframe = schema.at("$defs").at("keyframe");
  EXPECT_EQ(keys_of(keyframe.at("properties")),
            (std::set<std::string>{"t", "p", "m", "w", "q", "turns"}));
  EXPECT_EQ(keyframe.at("additionalProperties"), false);
  const nlohmann::json& options = schema.at("properties").at("options");
  EXPECT_EQ(keys_of(options.at("properties")),
            (std::set<std::string>{"anchor", "path_mean", "magnitude_mean"}));
  EXPECT_EQ(options.at("additionalProperties"), false);
  const nlohmann::json& samples = schema.at("properties").at("samples");
  EXPECT_EQ(samples.at("minimum"), kMinSamples);
  EXPECT_EQ(samples.at("maximum"), kMaxSamples);
}

TEST(SceneSchema, ListsEveryMethodForAutocomplete) {
  const nlohmann::json schema = read_json(kSourceDir / "schema/scene.schema.json");
  std::vector<std::string> ids;
  for (const MethodInfo& method : all_methods()) ids.emplace_back(method.id);
  EXPECT_EQ(schema.at("properties").at("method").at("examples").get<std::vector<std::string>>(), ids);
}

TEST(SceneFiles, EveryStarterSceneParses) {
  const std::vector<std::filesystem::path> files = scene_files();
  ASSERT_FALSE(files.empty()) << "no scenes in " << kSourceDir / "scenes";
  for (const std::filesystem::path& path : files) {
    SCOPED_TRACE(path.string());
    Scene scene;
    EXPECT_NO_THROW(scene = load_scene(path));
    EXPECT_FALSE(scene.description.empty());
    // Each names the schema, by a path that resolves from the scene's folder.
    const nlohmann::json document = read_json(path);
    ASSERT_TRUE(document.contains("$schema"));
    const std::filesystem::path schema = path.parent_path() / document["$schema"].get<std::string>();
    EXPECT_TRUE(std::filesystem::exists(schema)) << schema;
  }
}

TEST(SceneFiles, NamedAfterTheirFigure) {
  for (const std::filesystem::path& path : scene_files()) {
    const std::string name = path.stem().string();
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    EXPECT_TRUE(name.size() > 6 && name.rfind("fig", 0) == 0 && digit(name[3]) && digit(name[4]) &&
                name[5] == '-')
        << name << " is not named figNN-*.json";
  }
}

}  // namespace
}  // namespace pita::scene
