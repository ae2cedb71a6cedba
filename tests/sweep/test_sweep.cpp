// The option parsers of src/sweep/sweep.cpp: shards, output kinds, and the
// ranges --merge reports missing (the runner itself: tests/cli/test_sweep.cpp).
#include <gtest/gtest.h>

#include "sweep/sweep.hpp"

namespace pita::sweep {
namespace {

TEST(Sweep, IndexRangesShardsAndFormats) {
  EXPECT_EQ(index_ranges({{0, 3}, {7, 7}, {9, 11}}), "0-3, 7, 9-11");
  EXPECT_EQ(index_ranges({}), "");
  EXPECT_EQ(parse_shard("2/5"), (std::pair{2, 5}));
  for (const char* bad : {"5/5", "-1/3", "1", "1/0", "a/b", "1/2x", "1//2", " 1/2", "+1/2", "1/ 2", "/2", "1/"}) {
    EXPECT_THROW((void)parse_shard(bad), SweepUsageError) << bad;
  }
  EXPECT_EQ(parse_output_kinds("svg,csv,svg").size(), 2u);
  EXPECT_THROW((void)parse_output_kinds("svg,gif"), SweepUsageError);
}

}  // namespace
}  // namespace pita::sweep
