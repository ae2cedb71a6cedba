// The located error (src/scene/located_error.hpp): what() says where and why,
// and every kind has exactly one row in the table the front ends answer from.
#include <algorithm>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "scene/located_error.hpp"
#include "scene/scene.hpp"

namespace pita::scene {
namespace {

TEST(LocatedError, SceneErrorsAreLocatedErrorsOfTheirKind) {
  const SceneError at_pointer("a.json", "/keyframes/1/m", "magnitude must be > 0 (got -2)");
  const LocatedError& error = at_pointer;
  EXPECT_EQ(error.kind(), LocatedKind::scene);
  EXPECT_STREQ(error.what(), "a.json: /keyframes/1/m: magnitude must be > 0 (got -2)");
  EXPECT_EQ(error.file(), "a.json");
  EXPECT_EQ(error.pointer(), "/keyframes/1/m");
  EXPECT_EQ(error.reason(), "magnitude must be > 0 (got -2)");
  EXPECT_EQ(error.line(), 0);
  EXPECT_EQ(error.column(), 0);

  const SceneError at_position("a.json", 3, 14, "malformed JSON: a comma is missing");
  EXPECT_STREQ(at_position.what(), "a.json:3:14: malformed JSON: a comma is missing");
  EXPECT_EQ(at_position.pointer(), "");
  EXPECT_EQ(at_position.line(), 3);
  EXPECT_EQ(at_position.column(), 14);
}

TEST(LocatedError, LeavesOutThePointerOfTheWholeDocument) {
  EXPECT_EQ(located("a.json", "", "not a scene"), "a.json: not a scene");
  EXPECT_EQ(located("a.json", "/method", "unknown"), "a.json: /method: unknown");
}

TEST(LocatedError, EveryKindHasOneRowOfAnswers) {
  std::set<LocatedKind> kinds;
  std::set<std::string_view> classes;
  for (const LocatedAnswer& row : kLocatedAnswers) {
    EXPECT_TRUE(kinds.insert(row.kind).second);
    EXPECT_TRUE(classes.insert(row.python_class).second);
    EXPECT_EQ(&answer(row.kind), &row);
  }
  for (const LocatedKind kind : {LocatedKind::scene, LocatedKind::no_motion, LocatedKind::render}) {
    EXPECT_TRUE(kinds.count(kind) == 1);
  }
  // docs/reference/exit-codes-and-limits.md: a bad input exits with 2.
  EXPECT_EQ(answer(LocatedKind::scene).exit_code, 2);
  EXPECT_EQ(answer(LocatedKind::scene).python_class, "SceneError");
  EXPECT_EQ(answer(LocatedKind::no_motion).python_class, "NoMotionError");
  EXPECT_EQ(answer(LocatedKind::render).python_class, "RenderError");
}

}  // namespace
}  // namespace pita::scene
