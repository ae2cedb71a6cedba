// The JSON text of a scene (src/scene/json_text.cpp): positions of syntax
// errors, NUL bytes, numbers beyond a double, members given twice, the
// nesting limit and the file size limit.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "scene/json_text.hpp"
#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace pita::scene {
namespace {

using Json = nlohmann::ordered_json;

SceneError json_error(const std::string& text) {
  try {
    parse_json(text, "t.json");
  } catch (const SceneError& error) {
    return error;
  }
  return SceneError("t.json", "", "(no error)");
}

TEST(JsonText, GoodTextKeepsMembersInDocumentOrder) {
  const Json document = parse_json(R"({"b": 1, "a": [1, 2, {"c": null}]})", "t.json");
  ASSERT_TRUE(document.is_object());
  EXPECT_EQ(document.begin().key(), "b");
  EXPECT_EQ(document["a"][2]["c"], nullptr);
}

TEST(JsonText, SyntaxErrorsHaveALineAndColumn) {
  const SceneError error = json_error("{\n  \"a\": [1,\n  ]\n}");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 3);
  EXPECT_EQ(error.pointer(), "");
  EXPECT_NE(error.reason().find("malformed JSON"), std::string::npos) << error.what();
}

TEST(JsonText, NulByteIsRefusedWhereItIs) {
  const SceneError error = json_error(std::string("{\"a\":\n 1\0}", 10));
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.column(), 3);
}

TEST(JsonText, NumberTooLargeForADoubleIsRefusedWhereItIs) {
  const SceneError error = json_error("{\"a\": [1, 2e999]}");
  EXPECT_EQ(error.line(), 1);
  EXPECT_EQ(error.column(), 11);  // where "2e999" starts
}

TEST(JsonText, MemberGivenTwiceIsNamedByItsPointer) {
  const SceneError error = json_error(R"({"a": {"b": 1, "b": 2}})");
  EXPECT_EQ(error.pointer(), "/a/b");
  EXPECT_EQ(error.line(), 0);
  EXPECT_EQ(json_error(R"({"a": [{"x": 1}, {"x": 2}]})").reason(), "(no error)");  // same key, other objects
}

std::string nested(std::size_t depth, const std::string& after = "") {
  return std::string(depth, '[') + std::string(depth, ']') + after;
}

TEST(JsonText, NestingUpToTheLimitIsRead) {
  EXPECT_TRUE(parse_json(nested(kMaxJsonDepth), "t.json").is_array());
  EXPECT_TRUE(parse_json("{\"a\": " + nested(kMaxJsonDepth - 1) + "}", "t.json").is_object());
}

TEST(JsonText, NestingBeyondTheLimitIsRefusedWhereItStarts) {
  const SceneError error = json_error(nested(kMaxJsonDepth + 1));
  EXPECT_EQ(error.line(), 1);
  EXPECT_EQ(error.column(), static_cast<int>(kMaxJsonDepth) + 1);
  EXPECT_NE(error.reason().find("nest deeper than 256"), std::string::npos) << error.what();
}

// Issue 11: 85 000 nested arrays followed by another member of the same
// object overflowed the stack inside nlohmann's DOM callback (SIGSEGV).
TEST(JsonText, VeryDeepNestingFollowedByAMemberIsAnErrorNotACrash) {
  const std::string text = "{\"a\": " + nested(200'000) + ", \"b\": 1}";
  EXPECT_EQ(json_error(text).line(), 1);
  const std::string objects = [] {
    std::string t;
    for (int i = 0; i < 200'000; ++i) t += "{\"k\":";
    return t + "1" + std::string(200'000, '}');
  }();
  EXPECT_NE(json_error(objects).reason().find("nest deeper"), std::string::npos);
}

TEST(JsonText, BracketsInsideStringsDoNotCount) {
  std::string text = "{\"a\": \"";
  text.append(1000, '[');
  text += "\\\"\"}";
  EXPECT_TRUE(parse_json(text, "t.json").is_object());
}

class InputFile : public ::testing::Test {
 protected:
  void TearDown() override { std::filesystem::remove(path_); }
  std::filesystem::path path_ =
      std::filesystem::temp_directory_path() / ("pita-test-input-" + std::to_string(::getpid()) + ".json");
};

TEST_F(InputFile, AFileAtTheLimitIsRead) {
  std::ofstream(path_) << std::string(100, ' ');
  EXPECT_EQ(read_input_file(path_, 100, "scene file").size(), 100u);
}

TEST_F(InputFile, ALargerFileIsRefusedWithTheLimit) {
  std::ofstream(path_) << std::string(2 << 20, ' ');
  try {
    read_input_file(path_, 1 << 20, "scene file");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.file(), path_.string());
    EXPECT_EQ(error.reason(), "the scene file is larger than the limit of 1 MiB");
  }
}

// Issue 11: `pita eval /dev/zero` read until memory ran out.
// An endless stream is no regular file: refused at once, never read to the
// limit (tests/io/test_input_file.cpp has every kind of file).
TEST(JsonTextFile, AnEndlessFileIsRefusedAtOnce) {
  try {
    read_input_file("/dev/zero", kMaxSceneFileBytes, "scene file");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.reason(), "cannot read the scene file: it is a device, not a regular file");
  }
}

TEST(JsonTextFile, ADirectoryOrAMissingFileIsNamed) {
  EXPECT_THROW(read_input_file("/", 100, "scene file"), SceneError);
  EXPECT_THROW(read_input_file("/nonexistent/x.json", 100, "scene file"), SceneError);
}

}  // namespace
}  // namespace pita::scene
