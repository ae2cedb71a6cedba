// The JSON text of a scene (src/scene/json_text.cpp): positions of syntax
// errors, NUL bytes, numbers beyond a double, members given twice.
#include <gtest/gtest.h>

#include <string>

#include "scene/json_text.hpp"
#include "scene/scene.hpp"

namespace pita::scene::detail {
namespace {

SceneError error_of(const std::string& text) {
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
  const SceneError error = error_of("{\n  \"a\": [1,\n  ]\n}");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 3);
  EXPECT_EQ(error.pointer(), "");
  EXPECT_NE(error.reason().find("malformed JSON"), std::string::npos) << error.what();
}

TEST(JsonText, NulByteIsRefusedWhereItIs) {
  const SceneError error = error_of(std::string("{\"a\":\n 1\0}", 10));
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.column(), 3);
}

TEST(JsonText, NumberTooLargeForADoubleIsRefusedWhereItIs) {
  const SceneError error = error_of("{\"a\": [1, 2e999]}");
  EXPECT_EQ(error.line(), 1);
  EXPECT_EQ(error.column(), 11);  // where "2e999" starts
}

TEST(JsonText, MemberGivenTwiceIsNamedByItsPointer) {
  const SceneError error = error_of(R"({"a": {"b": 1, "b": 2}})");
  EXPECT_EQ(error.pointer(), "/a/b");
  EXPECT_EQ(error.line(), 0);
  EXPECT_EQ(error_of(R"({"a": [{"x": 1}, {"x": 2}]})").reason(), "(no error)");  // same key, other objects
}

}  // namespace
}  // namespace pita::scene::detail
