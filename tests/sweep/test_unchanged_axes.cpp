// The axes of a sweep that changed nothing (src/sweep/unchanged_axes.cpp):
// digests made from chosen axes' values, so the answer is known.
#include <gtest/gtest.h>

#include "sweep/unchanged_axes.hpp"

namespace pita::sweep {
namespace {

Grid grid_of(const std::vector<std::string>& vary, bool zip = false) {
  std::vector<Axis> axes;
  for (const std::string& v : vary) axes.push_back(parse_axis(v));
  return Grid(std::move(axes), zip);
}

TEST(UnchangedAxes, NamesTheAxesTheDigestsDoNotDependOn) {
  // 3 x 4 x 2 variants; the digest depends on the first and last axes only.
  const Grid grid = grid_of({"/a=1,2,3", "/b=1,2,3,4", "/c=x,y"});
  UnchangedAxes axes(grid);
  for (std::int64_t i = 0; i < grid.size(); ++i) {
    const std::vector<std::size_t> at = grid.positions(i);
    axes.add(i, 1 + at[0] * 10 + at[2]);
  }
  EXPECT_EQ(axes.unchanged(), std::vector<std::string>{"/b"});
}

TEST(UnchangedAxes, OneDifferenceIsEnoughAndMissingDigestsAreNotCompared) {
  const Grid grid = grid_of({"/a=1,2", "/b=1,2,3"});
  UnchangedAxes axes(grid);
  for (std::int64_t i = 0; i < grid.size(); ++i) {
    // /b changes the outputs in one place only (a = 2, b = 3); a failed
    // variant (a = 1, b = 2) gives no digest.
    const std::vector<std::size_t> at = grid.positions(i);
    const std::uint64_t digest = at[0] == 1 && at[1] == 2 ? 99 : 1 + at[0];
    axes.add(i, at[0] == 0 && at[1] == 1 ? 0 : digest);
  }
  EXPECT_TRUE(axes.unchanged().empty());
  // Nothing compared: nothing named.
  UnchangedAxes none(grid);
  none.add(0, 5);
  EXPECT_TRUE(none.unchanged().empty());
}

TEST(UnchangedAxes, ZippedAxesMoveTogether) {
  const Grid grid = grid_of({"/a=1,2,3", "/b=4,5,6"}, true);
  UnchangedAxes same(grid), differ(grid);
  for (std::int64_t i = 0; i < grid.size(); ++i) {
    same.add(i, 7);
    differ.add(i, 7 + static_cast<std::uint64_t>(i));
  }
  EXPECT_EQ(same.unchanged(), (std::vector<std::string>{"/a", "/b"}));
  EXPECT_TRUE(differ.unchanged().empty());
}

}  // namespace
}  // namespace pita::sweep
