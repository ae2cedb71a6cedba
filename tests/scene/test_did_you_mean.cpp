// "Did you mean" suggestions (src/scene/did_you_mean.cpp).
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "scene/did_you_mean.hpp"

namespace pita::scene {
namespace {

using Names = std::vector<std::string>;

TEST(EditDistance, CountsEditsIgnoringCase) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("samples", "smaples"), 2u);
  EXPECT_EQ(edit_distance("Keyframes", "keyframes"), 0u);
  EXPECT_EQ(edit_distance("keyframe", "keyframes"), 1u);
}

TEST(ClosestNames, WithinTwoEditsBestFirst) {
  constexpr std::array<std::string_view, 6> kFields = {"t", "p", "m", "w", "q", "turns"};
  EXPECT_EQ(closest_names("mm", kFields), Names{"m"});
  EXPECT_EQ(closest_names("T", kFields), Names{"t"});
  EXPECT_EQ(closest_names("turn", kFields), Names{"turns"});
  // One letter is one edit away from every one-letter field: no suggestion.
  EXPECT_EQ(closest_names("x", kFields), Names{});
  EXPECT_EQ(closest_names("colour", kFields), Names{});
  constexpr std::array<std::string_view, 3> kMeans = {"arithmetic", "geometric", "harmonic"};
  EXPECT_EQ(closest_names("geometic", kMeans), Names{"geometric"});
  EXPECT_EQ(closest_names("xyz", kMeans), Names{});
  constexpr std::array<std::string_view, 2> kTies = {"ab", "ba"};
  EXPECT_EQ(closest_names("aa", kTies), (Names{"ab", "ba"}));
}

TEST(DidYouMean, Formatting) {
  EXPECT_EQ(alternatives(Names{"a"}), "\"a\"");
  EXPECT_EQ(alternatives(Names{"a", "b"}), "\"a\" or \"b\"");
  EXPECT_EQ(alternatives(Names{"a", "b", "c"}, false), "a, b or c");
  EXPECT_EQ(did_you_mean(Names{}), "");
  EXPECT_EQ(did_you_mean(Names{"eval"}), "; did you mean \"eval\"?");
}

}  // namespace
}  // namespace pita::scene
