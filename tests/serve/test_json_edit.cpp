// Edits of JSON text that keep the rest of it (src/serve/json_edit.cpp): the
// value at a pointer is found in objects and arrays, with escapes in keys and
// in pointers, and replacing it changes those bytes only.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "serve/json_edit.hpp"

namespace pita::serve {
namespace {

const std::string kEditText = R"({
  "method": "P6",
  "keyframes": [
    {"t": 0,   "p": [0, 0],   "m": 1.50, "w": 0.4},
    {"t": 0.5, "p": [3, 1.5], "q": [3.5, 2]}
  ],
  "a/b": {"~x": "s \" ] } ,"},
  "empty": [], "none": {}
})";

std::string at(const std::string& pointer) {
  const TextSpan span = value_span(kEditText, pointer);
  return kEditText.substr(span.begin, span.end - span.begin);
}

TEST(JsonEdit, FindsValuesInObjectsAndArrays) {
  EXPECT_EQ(at("/method"), R"("P6")");
  EXPECT_EQ(at("/keyframes/0/m"), "1.50");
  EXPECT_EQ(at("/keyframes/1/q"), "[3.5, 2]");
  EXPECT_EQ(at("/keyframes/1/q/1"), "2");
  EXPECT_EQ(at("/keyframes/1"), R"({"t": 0.5, "p": [3, 1.5], "q": [3.5, 2]})");
  EXPECT_EQ(at("/a~1b/~0x"), R"("s \" ] } ,")");  // ~1 is /, ~0 is ~; brackets inside a string
  EXPECT_EQ(at("/empty"), "[]");
  EXPECT_EQ(at(""), kEditText);
}

TEST(JsonEdit, ReplacingChangesThoseBytesOnly) {
  const std::string edited = replace_value(kEditText, "/keyframes/0/p", "[1, -2.25]");
  std::string expected = kEditText;
  expected.replace(expected.find("[0, 0]"), 6, "[1, -2.25]");
  EXPECT_EQ(edited, expected);
  EXPECT_EQ(nlohmann::json::parse(edited)["keyframes"][0]["p"], nlohmann::json::parse("[1, -2.25]"));
  EXPECT_NE(edited.find(R"("m": 1.50)"), std::string::npos);  // an untouched number keeps its spelling
}

TEST(JsonEdit, AbsentValuesAreRefused) {
  for (const char* pointer : {"/keyframes/2", "/keyframes/x", "/nothing", "/method/0", "/empty/0", "/none/a", "nope"}) {
    EXPECT_THROW(value_span(kEditText, pointer), std::invalid_argument) << pointer;
  }
  EXPECT_THROW(value_span("{\"a\": [1, 2", "/a/1"), std::invalid_argument);
  EXPECT_THROW(value_span("{\"a\" 1}", "/a"), std::invalid_argument);
}

}  // namespace
}  // namespace pita::serve
