// Which motions read a method option, and the message when none does
// (src/scene/option_use.cpp); the refusals themselves are data files
// (tests/data/bad/options-anchor-not-read.json, ...).
#include <gtest/gtest.h>

#include "scene/option_use.hpp"
#include "scene/scene.hpp"
#include "scene_test_support.hpp"

namespace pita::scene {
namespace {

using test::p6_with;

MotionKeys keys_of(const std::string& json) { return parse_scene(json, "s.json").keys; }

TEST(OptionUse, AMethodReadsItsOwnOptionsTheKnotOrderAndAChainsMeans) {
  const std::string p6 = p6_with("");
  std::string p2 = p6;
  p2.replace(p2.find("\"P6\""), 4, "\"P2\"");
  EXPECT_TRUE(keys_read_option(keys_of(p2), kAnchorOption));
  EXPECT_FALSE(keys_read_option(keys_of(p6), kAnchorOption));
  EXPECT_TRUE(keys_read_option(keys_of(p6), kKnotsOption));  // every three-keyframe method
  EXPECT_FALSE(keys_read_option(keys_of(p6), kPathMeanOption));
  // Chained past its three keyframes, P6 builds steady morphs, which read the means.
  EXPECT_TRUE(keys_read_option(keys_of(p6_with(R"(, "chain": "spiral")")), kPathMeanOption));
}

TEST(OptionUse, TheMessageNamesTheMethodsAndTheReaders) {
  const std::array<Method, 1> p6{Method::P6};
  EXPECT_EQ(unread_option_reason(p6, "anchor", kAnchorOption),
            "P6 La-LP does not read \"anchor\", so it would change nothing here; P2 reads it");
  const std::array<Method, 3> several{Method::P6, Method::P8, Method::P6};
  EXPECT_EQ(unread_option_reason(several, "anchor", kAnchorOption),
            "none of the methods it applies to (P6 La-LP, P8 Lo-Pe) reads \"anchor\", so it would change nothing "
            "here; P2 reads it");
}

}  // namespace
}  // namespace pita::scene
