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

// "Save view" adds "camera" members a scene lacks: each added as its
// object's last member, spaced as the member before it, and removing it
// gives the text back byte for byte (undo).
TEST(JsonEdit, AddingAMemberKeepsEveryOtherByte) {
  const std::string pretty = "{\n  \"dimension\": 3,\n  \"camera\": {\n    \"shadow\": true\n  }\n}\n";
  Undo undo;
  const std::string added = set_value(pretty, "/camera/azimuth", "-52.5", &undo);
  EXPECT_EQ(added, "{\n  \"dimension\": 3,\n  \"camera\": {\n    \"shadow\": true,\n    \"azimuth\": -52.5\n  }\n}\n");
  EXPECT_EQ(undo.pointer, "/camera/azimuth");
  EXPECT_FALSE(undo.value);
  EXPECT_EQ(remove_member(added, undo.pointer), pretty);

  // On one line, as the object is; a value that is there is replaced, and its old text is the undo.
  const std::string inline_ = R"({"t": 1, "camera": {"azimuth": -60, "elevation": 55, "auto": true}})";
  const std::string turned = set_value(set_value(inline_, "/camera/azimuth", "10", &undo), "/camera/distance", "4");
  EXPECT_EQ(undo.pointer, "/camera/azimuth");
  EXPECT_EQ(undo.value, "-60");
  EXPECT_EQ(turned, R"({"t": 1, "camera": {"azimuth": 10, "elevation": 55, "auto": true, "distance": 4}})");
  EXPECT_EQ(remove_member(turned, "/camera/distance"),
            R"({"t": 1, "camera": {"azimuth": 10, "elevation": 55, "auto": true}})");
}

TEST(JsonEdit, MissingObjectsOnTheWayAreAdded) {
  const std::string text = "{\n  \"method\": \"polySAM\",\n  \"poses\": []\n}";
  Undo undo;
  const std::string once = set_value(text, "/camera/azimuth", "30", &undo);
  EXPECT_EQ(once, "{\n  \"method\": \"polySAM\",\n  \"poses\": [],\n  \"camera\": {\"azimuth\": 30}\n}");
  EXPECT_EQ(undo.pointer, "/camera");  // the object added, removed whole
  EXPECT_FALSE(undo.value);
  Undo second;
  const std::string twice = set_value(once, "/camera/elevation", "20", &second);
  EXPECT_EQ(nlohmann::json::parse(twice)["camera"], nlohmann::json::parse(R"({"azimuth": 30, "elevation": 20})"));
  EXPECT_EQ(remove_member(remove_member(twice, second.pointer), undo.pointer), text);
  // Into empty objects, and the only member removed again.
  EXPECT_EQ(set_value("{}", "/a/b", "1"), R"({"a": {"b": 1}})");
  EXPECT_EQ(set_value("{ }", "/a", "true"), R"({"a": true })");
  EXPECT_EQ(remove_member(R"({"a": true })", "/a"), "{ }");
  // The first of several members, and one in the middle.
  EXPECT_EQ(remove_member(R"({"a": 1, "b": 2, "c": 3})", "/a"), R"({"b": 2, "c": 3})");
  EXPECT_EQ(remove_member(R"({"a": 1, "b": 2, "c": 3})", "/b"), R"({"a": 1, "c": 3})");
  // A key that needs escapes is written as JSON, and found again.
  const std::string odd = set_value("{}", "/q\"~1x", "0");
  EXPECT_EQ(odd, R"({"q\"/x": 0})");
  EXPECT_EQ(nlohmann::json::parse(odd).begin().key(), "q\"/x");
}

TEST(JsonEdit, NothingIsAddedToArraysOrScalars) {
  EXPECT_THROW(set_value(kEditText, "/keyframes/5", "{}"), std::invalid_argument);
  EXPECT_THROW(set_value(kEditText, "/method/x", "1"), std::invalid_argument);
  EXPECT_THROW(set_value(kEditText, "/empty/0/x", "1"), std::invalid_argument);
  EXPECT_THROW(set_value("{\"a\": [1", "/b", "1"), std::invalid_argument);
  EXPECT_THROW(remove_member(kEditText, "/nothing"), std::invalid_argument);
  EXPECT_THROW(remove_member(kEditText, "/keyframes/0"), std::invalid_argument);
}

}  // namespace
}  // namespace pita::serve
