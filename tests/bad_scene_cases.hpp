// The bad-scene cases of tests/data/bad/ (README.md there): one scene per
// <name>.json, with the error it must give in <name>.expect. Read by
// tests/scene/test_bad_scenes.cpp (load_scene) and
// tests/cli/test_bad_scenes_cli.cpp (the pita binary). Needs PITA_SOURCE_DIR.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace pita::test {

inline const std::filesystem::path kBadScenesDir = std::filesystem::path(PITA_SOURCE_DIR) / "tests/data/bad";

// Folders of files that cases name, beside the cases (images/: the PNG and
// not-PNG files of the images-* cases; pita looks for images relative to the
// scene's folder). tests/cli/test_bad_scenes_cli.cpp copies them beside each
// case it runs.
inline const std::vector<std::string> kBadSceneFixtureFolders = {"images"};

// Fewer cases than this means the folder was not found or not read: the
// tests must not pass on an empty list.
inline constexpr std::size_t kMinBadScenes = 50;

// Only the name is kept: every test process registers all the cases, and
// under the sanitizers the three std::filesystem::path of each case (a list of
// components each, copied into every registered test) were most of a test
// process's start-up (docs/explanation/build-time.md "Build time").
struct BadSceneCase {
  std::string name;  // the file stem, "keyframes-m-negative"

  std::filesystem::path scene() const { return kBadScenesDir / (name + ".json"); }
  std::filesystem::path expect() const { return kBadScenesDir / (name + ".expect"); }
};

// Test names print the case, not the bytes of the struct.
inline void PrintTo(const BadSceneCase& bad, std::ostream* out) { *out << bad.name; }

// What a .expect file says.
struct BadSceneExpectation {
  bool at_position = false;  // "position: L:C" (malformed text) rather than "pointer: ..."
  std::string pointer;       // "" = the whole document (only when !at_position)
  int line = 0;              // 1-based (only when at_position)
  int column = 0;
  std::string reason;

  // What follows the file name in SceneError::what(): ": /p: reason",
  // ": reason" (whole document) or ":L:C: reason".
  // (Appended piece by piece: GCC 12 warns falsely, -Wrestrict, about "..." + std::string.)
  std::string after_file() const {
    std::string text = ":";
    if (at_position) {
      text += std::to_string(line);
      text += ':';
      text += std::to_string(column);
      text += ':';
    } else if (!pointer.empty()) {
      text += ' ';
      text += pointer;
      text += ':';
    }
    text += ' ';
    text += reason;
    return text;
  }
};

// Every <name>.json of the folder, sorted by name (none when the folder is missing).
inline std::vector<BadSceneCase> bad_scene_cases() {
  std::vector<BadSceneCase> cases;
  std::error_code error;
  for (std::filesystem::directory_iterator it(kBadScenesDir, error), end; !error && it != end; it.increment(error)) {
    const std::filesystem::path& path = it->path();
    if (path.extension() != ".json") continue;
    cases.push_back({path.stem().string()});
  }
  std::sort(cases.begin(), cases.end(), [](const BadSceneCase& a, const BadSceneCase& b) { return a.name < b.name; });
  return cases;
}

// The test name of a case: its name with every character other than a
// letter or a digit replaced by '_'.
inline std::string bad_scene_test_name(const ::testing::TestParamInfo<BadSceneCase>& info) {
  std::string name = info.param.name;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

// What is wrong with the folder: a .json without its .expect or the other way
// round, another kind of file, a folder other than the fixture folders, too
// few cases. Empty when all is well.
inline std::vector<std::string> bad_scene_folder_problems() {
  std::vector<std::string> problems;
  if (!std::filesystem::is_directory(kBadScenesDir)) {
    problems.push_back(kBadScenesDir.string() + ": not a directory");
    return problems;
  }
  std::size_t scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kBadScenesDir)) {
    const std::filesystem::path& path = entry.path();
    const std::string file = path.filename().string();
    if (path.extension() == ".json") {
      ++scenes;
      if (!std::filesystem::exists(std::filesystem::path(path).replace_extension(".expect"))) {
        problems.push_back(file + ": no " + path.stem().string() + ".expect beside it");
      }
    } else if (path.extension() == ".expect") {
      if (!std::filesystem::exists(std::filesystem::path(path).replace_extension(".json"))) {
        problems.push_back(file + ": no " + path.stem().string() + ".json beside it");
      }
    } else if (entry.is_directory()) {
      if (std::find(kBadSceneFixtureFolders.begin(), kBadSceneFixtureFolders.end(), file) ==
          kBadSceneFixtureFolders.end()) {
        problems.push_back(file + ": a folder other than the fixtures' (images/)");
      }
    } else if (file != "README.md") {
      problems.push_back(file + ": neither a .json case nor its .expect");
    }
  }
  if (scenes < kMinBadScenes) {
    problems.push_back("only " + std::to_string(scenes) + " cases (at least " + std::to_string(kMinBadScenes) +
                       " expected)");
  }
  return problems;
}

// Reads a .expect file: exactly two lines,
//   pointer: /keyframes/1/m      (nothing after the colon: the whole document)
//   reason: magnitude must be > 0 (got -2)
// or, for an error at a position of the text,
//   position: 3:22
//   reason: malformed JSON: ...
// Returns nothing and sets `problem` when the file is not of this form.
inline std::optional<BadSceneExpectation> read_bad_scene_expectation(const std::filesystem::path& path,
                                                                     std::string& problem) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    problem = "cannot open " + path.string();
    return std::nullopt;
  }
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::string text = bytes.str();
  if (!text.empty() && text.back() == '\n') text.pop_back();
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    lines.push_back(text.substr(start, end - start));
  }
  lines.push_back(text.substr(start));

  // The value after "key:", without the one space that follows the colon.
  const auto value_of = [](const std::string& line, const std::string& key) -> std::optional<std::string> {
    if (line.rfind(key + ":", 0) != 0) return std::nullopt;
    std::string value = line.substr(key.size() + 1);
    if (!value.empty() && value.front() == ' ') value.erase(0, 1);
    return value;
  };

  problem = path.filename().string() + ": ";
  if (lines.size() != 2) {
    problem += "must have two lines, \"pointer: ...\" or \"position: L:C\", then \"reason: ...\" (got " +
               std::to_string(lines.size()) + ")";
    return std::nullopt;
  }
  BadSceneExpectation expected;
  if (const auto pointer = value_of(lines[0], "pointer")) {
    if (!pointer->empty() && pointer->front() != '/') {
      problem += "the pointer must be empty or start with '/' (got \"" + *pointer + "\")";
      return std::nullopt;
    }
    expected.pointer = *pointer;
  } else if (const auto position = value_of(lines[0], "position")) {
    expected.at_position = true;
    char colon = 0;
    std::istringstream numbers(*position);
    if (!(numbers >> expected.line >> colon >> expected.column) || colon != ':' || !numbers.eof() ||
        expected.line < 1 || expected.column < 1) {
      problem += "the position must be L:C, two numbers >= 1 (got \"" + *position + "\")";
      return std::nullopt;
    }
  } else {
    problem += "the first line must start with \"pointer:\" or \"position:\" (got \"" + lines[0] + "\")";
    return std::nullopt;
  }
  const auto reason = value_of(lines[1], "reason");
  if (!reason || reason->empty()) {
    problem += "the second line must be \"reason: ...\" with a reason (got \"" + lines[1] + "\")";
    return std::nullopt;
  }
  expected.reason = *reason;
  problem.clear();
  return expected;
}

}  // namespace pita::test
