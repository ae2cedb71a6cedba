// The chain table, span lookup and make_chain's refusals (core/chains/chain.hpp).
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/chains/chain.hpp"
#include "core/limits.hpp"
#include "core/pitas/registry.hpp"
#include "track_support.hpp"

namespace pita {
namespace {

TEST(ChainTable, NamesAreUniqueAndFoundExactly) {
  std::set<std::string_view> names;
  for (const ChainInfo& about : all_chains()) {
    EXPECT_TRUE(names.insert(about.name).second) << about.name;
    ASSERT_NE(find_chain(about.name), nullptr);
    EXPECT_EQ(find_chain(about.name)->chain, about.chain);
    EXPECT_EQ(&info(about.chain), &about);
    EXPECT_NE(chain_names().find(std::string(about.name)), std::string::npos);
  }
  EXPECT_EQ(names.size(), 4u);
  EXPECT_EQ(find_chain("Blend"), nullptr);
  EXPECT_EQ(find_chain("bezier_spiral"), nullptr);
  EXPECT_EQ(find_chain(""), nullptr);
}

TEST(ChainTable, DefaultIsSpiralForTheSmaAndBlendForThreeKeyframeMethods) {
  EXPECT_EQ(default_chain(Method::SMA), Chain::spiral);
  for (const MethodInfo& about : all_methods()) {
    if (about.keyframe_count == 3) {
      EXPECT_EQ(default_chain(about.method), Chain::blend) << about.id;
    }
  }
}

TEST(SpanOf, FindsTheSpanAndClampsOutside) {
  const std::vector<double> knots{0.0, 1.0, 2.5, 4.0};
  EXPECT_EQ(span_of(knots, -10.0), 0u);
  EXPECT_EQ(span_of(knots, 0.0), 0u);
  EXPECT_EQ(span_of(knots, 0.999), 0u);
  EXPECT_EQ(span_of(knots, 1.0), 1u);
  EXPECT_EQ(span_of(knots, 2.49), 1u);
  EXPECT_EQ(span_of(knots, 2.5), 2u);
  EXPECT_EQ(span_of(knots, 4.0), 2u);  // the last knot belongs to the last span
  EXPECT_EQ(span_of(knots, 1e300), 2u);
  EXPECT_LE(span_of(knots, std::numeric_limits<double>::quiet_NaN()), 2u);  // a span, whichever
}

TEST(MakeMotion, RefusesTooFewKeyframesAndUnorderedKnotsNamingTheIndex) {
  test::TrackSampler s(5);
  std::vector<Keyframe> keys = s.track(6);
  EXPECT_THROW(make_motion(Method::P6, std::span(keys).first(2)), std::invalid_argument);
  EXPECT_THROW(make_motion(Method::SMA, std::span(keys).first(1)), std::invalid_argument);
  keys[4].t = keys[3].t;
  try {
    (void)make_motion(Method::P6, keys);
    FAIL() << "equal knots accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("keyframe 4"), std::string::npos) << error.what();
  }
}

TEST(MakeMotion, BlendOnTheSmaIsRefusedWithTheAlternatives) {
  test::TrackSampler s(6);
  const std::vector<Keyframe> keys = s.track(5);
  try {
    (void)make_motion(Method::SMA, keys, {}, Chain::blend);
    FAIL() << "blend of the SMA accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("P9"), std::string::npos) << error.what();
  }
  for (const Chain chain : {Chain::spiral, Chain::bezier_spiral, Chain::neville}) {
    EXPECT_NO_THROW((void)make_motion(Method::SMA, keys, {}, chain)) << info(chain).name;
  }
}

TEST(MakeMotion, NevilleRefusesMoreThanItsLimit) {
  test::TrackSampler s(7);
  const std::vector<Keyframe> keys = s.track(limits::kMaxNevilleKeyframes + 1);
  EXPECT_THROW((void)make_motion(Method::P6, keys, {}, Chain::neville), std::invalid_argument);
  EXPECT_NO_THROW(
      (void)make_motion(Method::P6, std::span(keys).first(limits::kMaxNevilleKeyframes), {}, Chain::neville));
  EXPECT_NO_THROW((void)make_motion(Method::P6, keys, {}, Chain::blend));
}

}  // namespace
}  // namespace pita
