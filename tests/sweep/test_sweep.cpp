// The ranges --merge reports missing, of src/sweep/sweep.cpp (the runner
// itself: tests/cli/test_sweep.cpp; the parsers of --shard and --format:
// tests/cli/test_sweep_options.cpp).
#include <gtest/gtest.h>

#include "sweep/sweep.hpp"

namespace pita::sweep {
namespace {

TEST(Sweep, IndexRanges) {
  EXPECT_EQ(index_ranges({{0, 3}, {7, 7}, {9, 11}}), "0-3, 7, 9-11");
  EXPECT_EQ(index_ranges({}), "");
}

}  // namespace
}  // namespace pita::sweep
